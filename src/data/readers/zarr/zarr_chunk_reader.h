// Finding and decoding one chunk of a Zarr array: its file from the chunk key encoding, inside a
// shard through the shard's index where the array is sharded; a chunk that is not stored is the
// array's fill value (the spec), one that is stored but cut short or damaged an InputError.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "zarr_array.h"

namespace tstyles {

// A shard file's index as read once: each of a shard's chunks is found through it, and a volume
// reads many chunks of one shard. `stored` is false for a shard file that is not there.
struct ZarrShardIndex {
    bool stored = false;
    std::uint64_t fileSize = 0;
    std::vector<std::uint8_t> entries;  // 16 bytes an inner chunk: offset, size (little-endian)
};
using ZarrShardIndexes = std::map<std::filesystem::path, ZarrShardIndex>;

// The chunk at `chunkIndex` (in chunks, one per dimension), decoded to array.chunkBytes() bytes;
// nullopt when it is not stored. `shardIndexes` keeps the indexes read (unused when not sharded).
std::optional<std::vector<std::uint8_t>> readZarrChunk(const ZarrArray& array, const std::vector<std::uint64_t>& chunkIndex,
                                                       ZarrShardIndexes& shardIndexes);

// The file a chunk (or, sharded, its shard) is stored in, from the array's key encoding.
std::filesystem::path zarrChunkFile(const ZarrArray& array, const std::vector<std::uint64_t>& fileIndex);

}  // namespace tstyles
