// NRRD volumes and volume series (.nrrd with attached data, .nhdr with a detached data file; raw or
// gzip). A 4D NRRD is a series along its non-spatial axis; a 3D NRRD is one time-step.
#pragma once

#include <filesystem>

#include "../source_series.h"

namespace tstyles {

SourceSeries openNrrd(const std::filesystem::path& file);

}  // namespace tstyles
