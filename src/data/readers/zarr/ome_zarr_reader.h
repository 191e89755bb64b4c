// OME-Zarr images on the local disk (OME-NGFF 0.4 on Zarr v2, 0.5 on Zarr v3; docs/readers/ome-zarr.md):
// the store's first multiscales image, one resolution level and one channel, its time axis as the
// series' time-steps and its z, y, x axes as the volume.
#pragma once

#include <filesystem>

#include "../source_series.h"
#include "tstyles/data/read_options.h"

namespace tstyles {

// `input` is the store's folder, or its zarr.json or .zattrs file.
SourceSeries openOmeZarr(const std::filesystem::path& input, const ReadOptions& options);

// A folder that is a Zarr group (zarr.json, .zattrs or .zgroup) whose name ends in .zarr or whose
// attributes name multiscales.
bool isOmeZarrFolder(const std::filesystem::path& folder);

}  // namespace tstyles
