// Zarr v3's codec list read into a ZarrArray: array-to-array codecs (only transpose that keeps the
// order), one array-to-bytes codec (bytes, or sharding_indexed with its own inner list), then
// bytes-to-bytes codecs (blosc, gzip, zstd, crc32c).
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "zarr_array.h"

namespace tstyles {

// Sets array.codecs, byteOrder and, for a sharded array, sharding (chunkShape becomes the inner
// chunks'). An unknown codec or a configuration this reader cannot follow is an InputError.
void readCodecPipeline(const nlohmann::json& codecs, const std::filesystem::path& file, ZarrArray& array);

}  // namespace tstyles
