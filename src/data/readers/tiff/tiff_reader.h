// TIFF volume series for microscopy: ImageJ hyperstacks, OME-TIFF, plain multi-page TIFFs, lists
// and folders of TIFF files (docs/readers/tiff.md).
#pragma once

#include <filesystem>
#include <vector>

#include "../source_series.h"
#include "tstyles/data/read_options.h"

namespace tstyles {

// One TIFF file, several (in the order given), or a folder of them (in natural name order).
SourceSeries openTiff(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options);

// The TIFF magic: "II*\0", "MM\0*" or BigTIFF's "II+\0", "MM\0+".
bool hasTiffSignature(const std::filesystem::path& file);

// A folder holding .tif or .tiff files and no series.json; by names only, nothing is opened.
bool isTiffFolder(const std::filesystem::path& folder);

}  // namespace tstyles
