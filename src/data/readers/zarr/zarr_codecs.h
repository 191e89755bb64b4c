// The bytes-to-bytes codecs of Zarr chunks (numcodecs' blosc, zlib, gzip, zstd and lz4; Zarr v3's
// gzip, zstd, blosc and crc32c): a stored chunk back to exactly the bytes it must hold, or an
// InputError naming the chunk file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tstyles {

enum class ZarrByteCodec { Blosc, Zlib, Gzip, Zstd, Lz4, Crc32c };

std::string toString(ZarrByteCodec codec);

// Undoes `codecs` (listed in the order they were applied when writing) on `stored`, which must
// then be `expected` bytes: a chunk cut short, damaged or of another size is an InputError naming
// `chunkFile`. The caller has checked `expected` against the memory limits.
std::vector<std::uint8_t> decodeChunkBytes(std::vector<std::uint8_t> stored, const std::vector<ZarrByteCodec>& codecs,
                                           std::size_t expected, const std::filesystem::path& chunkFile);

// CRC-32C (Castagnoli) of `size` bytes, as Zarr v3's crc32c codec stores it.
std::uint32_t crc32c(const std::uint8_t* bytes, std::size_t size);

}  // namespace tstyles
