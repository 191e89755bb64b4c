// One Zarr array's metadata (v2 `.zarray` or v3 `zarr.json`): shape, chunking, data type, fill
// value, codecs and where its chunk files are. Everything a chunk read needs, checked on opening.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "../../value_decoding.h"
#include "tstyles/data/series.h"
#include "zarr_codecs.h"

namespace tstyles {

// Zarr v3's sharding_indexed codec: chunks (ZarrArray::chunkShape) packed into shard files of
// `shardShape` elements, found through an index of (offset, size) pairs at the file's start or end.
struct ZarrSharding {
    std::vector<std::uint64_t> shardShape;
    bool indexAtEnd = true;
    bool indexChecksummed = false;  // the index ends with a CRC-32C
};

struct ZarrArray {
    std::filesystem::path folder;
    std::filesystem::path metadataFile;  // .zarray or zarr.json, for messages
    int zarrFormat = 2;
    std::vector<std::uint64_t> shape;
    std::vector<std::uint64_t> chunkShape;  // of the chunks read: a sharded array's inner chunks
    ValueType type = ValueType::UInt8;
    ByteOrder byteOrder = ByteOrder::Little;
    std::string dataTypeText;  // as the file spells it, for notes
    bool fortranOrder = false;  // v2 "order": "F": the first index varies fastest within a chunk
    double fillValue = 0.0;     // NaN: a float array's missing value
    std::vector<ZarrByteCodec> codecs;  // in the order they were applied when writing
    bool v2ChunkKeys = true;            // "0.0.0" (v2) or "c/0/0/0" (v3's default encoding)
    char keySeparator = '.';
    std::optional<ZarrSharding> sharding;

    std::size_t chunkValues() const;
    std::size_t chunkBytes() const { return chunkValues() * bytesPerValue(type); }
};

// Reads and checks the array in `folder`; `zarrFormat` is the store's (2: `.zarray`, 3: `zarr.json`).
// A missing or malformed file, an unknown codec or data type, or chunks that do not fit the
// memory cap is an InputError naming the metadata file and the field.
ZarrArray readZarrArray(const std::filesystem::path& folder, int zarrFormat, std::uint64_t memoryCap);

}  // namespace tstyles
