// Chunk files and shard indexes read with their sizes checked before anything is allocated.
#include "zarr_chunk_reader.h"

#include <fstream>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

// A compressor never makes a chunk much larger than it was (blosc adds a 16-byte header, gzip a few
// bytes per 16 KiB); a stored chunk larger than this is not a chunk of this array.
std::uint64_t largestStoredChunk(const ZarrArray& array) {
    return std::uint64_t(array.chunkBytes()) * 2 + 65536;
}

std::vector<std::uint8_t> readBytes(const std::filesystem::path& file, std::uint64_t offset, std::uint64_t count) {
    std::vector<std::uint8_t> bytes(count);
    std::ifstream in(file, std::ios::binary);
    in.seekg(std::streamoff(offset));
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(count));
    if (!in) throwInputError(file, "", "cannot be read (" + std::to_string(count) + " bytes from byte " + std::to_string(offset) + ")");
    return bytes;
}

std::uint64_t littleEndian64(const std::uint8_t* bytes) {
    std::uint64_t value = 0;
    for (int index = 7; index >= 0; --index) value = value << 8 | bytes[index];
    return value;
}

std::optional<std::vector<std::uint8_t>> decodeStored(const ZarrArray& array, std::vector<std::uint8_t> stored,
                                                      const std::filesystem::path& chunkFile) {
    return decodeChunkBytes(std::move(stored), array.codecs, array.chunkBytes(), chunkFile);
}

const ZarrShardIndex& shardIndexOf(const ZarrArray& array, const std::filesystem::path& shardFile, std::uint64_t innerCount,
                                   ZarrShardIndexes& shardIndexes) {
    const auto known = shardIndexes.find(shardFile);
    if (known != shardIndexes.end()) return known->second;
    ZarrShardIndex& index = shardIndexes[shardFile];
    std::error_code error;
    if (!std::filesystem::exists(shardFile, error)) return index;
    const ZarrSharding& sharding = *array.sharding;
    index.stored = true;
    index.fileSize = regularFileSize(shardFile, "Zarr shard");
    const std::uint64_t indexBytes = innerCount * 16 + (sharding.indexChecksummed ? 4 : 0);
    if (innerCount > index.fileSize || indexBytes > index.fileSize)
        throwInputError(shardFile, "", "is cut short: its index needs " + std::to_string(indexBytes) + " bytes, the file has " +
                                           std::to_string(index.fileSize));
    index.entries = readBytes(shardFile, sharding.indexAtEnd ? index.fileSize - indexBytes : 0, indexBytes);
    if (sharding.indexChecksummed)
        index.entries = decodeChunkBytes(std::move(index.entries), {ZarrByteCodec::Crc32c}, indexBytes - 4, shardFile);
    return index;
}

// The inner chunk's bytes within its shard file, through the index (16 bytes an inner chunk:
// offset and size, both 2^64 - 1 for a chunk not stored).
std::optional<std::vector<std::uint8_t>> readShardedChunk(const ZarrArray& array, const std::vector<std::uint64_t>& chunkIndex,
                                                          ZarrShardIndexes& shardIndexes) {
    const ZarrSharding& sharding = *array.sharding;
    std::vector<std::uint64_t> shardIndex(chunkIndex.size());
    std::uint64_t innerCount = 1;
    std::uint64_t innerPosition = 0;
    for (std::size_t axis = 0; axis < chunkIndex.size(); ++axis) {
        const std::uint64_t perShard = sharding.shardShape[axis] / array.chunkShape[axis];
        shardIndex[axis] = chunkIndex[axis] / perShard;
        innerPosition = innerPosition * perShard + chunkIndex[axis] % perShard;
        innerCount *= perShard;
        // The index holds 16 bytes an inner chunk; past 2^40 of them no shard file can hold it.
        if (innerCount > std::uint64_t(1) << 40)
            throwInputError(array.metadataFile, "codecs", "a shard holds more than 2^40 inner chunks");
    }
    const std::filesystem::path shardFile = zarrChunkFile(array, shardIndex);
    const ZarrShardIndex& index = shardIndexOf(array, shardFile, innerCount, shardIndexes);
    if (!index.stored) return std::nullopt;
    const std::uint64_t offset = littleEndian64(index.entries.data() + innerPosition * 16);
    const std::uint64_t size = littleEndian64(index.entries.data() + innerPosition * 16 + 8);
    if (offset == ~std::uint64_t(0) && size == ~std::uint64_t(0)) return std::nullopt;
    if (offset > index.fileSize || size > index.fileSize - offset || size > largestStoredChunk(array))
        throwInputError(shardFile, "", "its index places inner chunk " + std::to_string(innerPosition) + " at bytes " +
                                           std::to_string(offset) + " + " + std::to_string(size) + ", outside the " +
                                           std::to_string(index.fileSize) + "-byte file or larger than a chunk");
    return decodeStored(array, readBytes(shardFile, offset, size),
                        shardFile.string() + " (inner chunk " + std::to_string(innerPosition) + ")");
}

}  // namespace

std::filesystem::path zarrChunkFile(const ZarrArray& array, const std::vector<std::uint64_t>& fileIndex) {
    std::string key = array.v2ChunkKeys ? "" : "c";
    for (std::size_t axis = 0; axis < fileIndex.size(); ++axis) {
        if (axis > 0 || !array.v2ChunkKeys) key += array.keySeparator;
        key += std::to_string(fileIndex[axis]);
    }
    // A zero-dimensional array's one chunk: "0" in v2, "c" in v3.
    if (fileIndex.empty() && array.v2ChunkKeys) key = "0";
    return array.folder / std::filesystem::path(key).make_preferred();
}

std::optional<std::vector<std::uint8_t>> readZarrChunk(const ZarrArray& array, const std::vector<std::uint64_t>& chunkIndex,
                                                       ZarrShardIndexes& shardIndexes) {
    if (array.sharding) return readShardedChunk(array, chunkIndex, shardIndexes);
    const std::filesystem::path chunkFile = zarrChunkFile(array, chunkIndex);
    std::error_code error;
    if (!std::filesystem::exists(chunkFile, error)) return std::nullopt;
    const std::uint64_t size = regularFileSize(chunkFile, "Zarr chunk");
    if (size > largestStoredChunk(array))
        throwInputError(chunkFile, "", "is " + std::to_string(size) + " bytes, more than a chunk of " +
                                           std::to_string(array.chunkBytes()) + " bytes can be stored in");
    return decodeStored(array, readBytes(chunkFile, 0, size), chunkFile);
}

}  // namespace tstyles
