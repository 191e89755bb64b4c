// DICOM series (folders of slices from a scanner, lists of files, enhanced multi-frame files)
// through GDCM: one series chosen by --series, its slices stacked into volumes and ordered in time
// by their tags, placed in the patient's RAS frame like NIfTI (docs/readers/dicom.md).
#pragma once

#include <filesystem>
#include <vector>

#include "../source_series.h"
#include "tstyles/data/read_options.h"

namespace tstyles {

// `inputs`: DICOM files, or folders of them (walked, nested folders included).
SourceSeries openDicom(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options);

}  // namespace tstyles
