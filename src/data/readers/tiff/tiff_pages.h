// Plain multi-page TIFFs and lists of TIFF files (a folder's): pages are z-slices of time-steps,
// in the order --axes gives (TZYX, time slowest, by default), --dims NXxNYxNZ saying how many
// slices make a volume.
#pragma once

#include <vector>

#include "tiff_imagej.h"
#include "tiff_layout.h"

namespace tstyles {

// `pages[f]` are file f's pages. Without --dims: one volume of every page, or one time-step per
// file when there are several multi-page files. `imagej` (the first file's, when it has one) gives
// the z spacing and the unit.
TiffLayout pageLayout(const std::vector<std::filesystem::path>& files, std::vector<std::vector<TiffPage>> pages,
                      const ImageJDescription* imagej, const ReadOptions& options);

}  // namespace tstyles
