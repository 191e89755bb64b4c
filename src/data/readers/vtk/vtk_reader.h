// VTK XML time series as ParaView keeps them: a .pvd collection, a .series file, one .vti/.vts file
// or a list of them (one time-step each, in the order given). docs/readers/vtk-xml.md.
#pragma once

#include <filesystem>
#include <vector>

#include "../source_series.h"
#include "tstyles/data/read_options.h"

namespace tstyles {

// `options.variable` (--var) picks the point array; a vector array is read as its magnitude.
SourceSeries openVtkSeries(const std::vector<std::filesystem::path>& files, const ReadOptions& options);

// Whether the file starts like a VTK XML or legacy VTK file, whatever its name.
bool hasVtkSignature(const std::filesystem::path& file);

}  // namespace tstyles
