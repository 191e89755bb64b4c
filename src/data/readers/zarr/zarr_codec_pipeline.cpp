// The v3 codec list, checked codec by codec, so that a chunk read only has to undo a known chain.
#include "zarr_codec_pipeline.h"

#include "tstyles/core/errors.h"
#include "tstyles/core/json_field.h"
#include "zarr_json.h"

namespace tstyles {
namespace {

struct Codec {
    std::string name;
    nlohmann::json configuration = nlohmann::json::object();
};

Codec readCodec(const nlohmann::json& value, const std::filesystem::path& file, const std::string& field) {
    Codec codec;
    codec.name = JsonField(file, value, field).member("name").string();
    if (value.contains("configuration")) codec.configuration = value["configuration"];
    if (!codec.configuration.is_object()) throwInputError(file, field + ".configuration", "must be an object");
    return codec;
}

// Transpose is only accepted when it keeps the order: any other would reorder the values within a chunk.
void requireIdentityTranspose(const Codec& codec, std::size_t dimensions, const std::filesystem::path& file,
                              const std::string& field) {
    const auto order = JsonField(file, codec.configuration, field + ".configuration").member("order").wholeNumbers(0);
    for (std::size_t index = 0; index < order.size(); ++index)
        if (order[index] != index || order.size() != dimensions)
            throwInputError(file, field, "a transpose that reorders the axes is not supported; rewrite the array in C order");
}

ByteOrder readEndian(const Codec& codec, const ZarrArray& array, const std::filesystem::path& file, const std::string& field) {
    if (!codec.configuration.contains("endian")) {
        if (bytesPerValue(array.type) > 1) throwInputError(file, field + ".configuration.endian", "is missing");
        return ByteOrder::Little;
    }
    const std::string endian = JsonField(file, codec.configuration["endian"], field + ".configuration.endian").string();
    if (endian != "little" && endian != "big")
        throwInputError(file, field + ".configuration.endian", "is \"" + endian + "\", not \"little\" or \"big\"");
    return endian == "big" ? ByteOrder::Big : ByteOrder::Little;
}

std::optional<ZarrByteCodec> byteCodecNamed(const std::string& name) {
    if (name == "blosc") return ZarrByteCodec::Blosc;
    if (name == "gzip") return ZarrByteCodec::Gzip;
    if (name == "zstd") return ZarrByteCodec::Zstd;
    if (name == "crc32c") return ZarrByteCodec::Crc32c;
    return std::nullopt;
}

bool isCompressor(ZarrByteCodec codec) { return codec != ZarrByteCodec::Crc32c; }

void readShardingConfiguration(const Codec& codec, const std::filesystem::path& file, const std::string& field,
                               ZarrArray& array);

// One list: array-to-array, one array-to-bytes, bytes-to-bytes. `allowSharding` is false inside a
// shard: nested shards are not supported.
void readCodecList(const nlohmann::json& list, const std::filesystem::path& file, const std::string& field,
                   bool allowSharding, ZarrArray& array) {
    if (!list.is_array() || list.empty()) throwInputError(file, field, "must be a non-empty list of codecs");
    bool toBytes = false;
    int compressors = 0;
    for (std::size_t index = 0; index < list.size(); ++index) {
        const std::string at = field + "[" + std::to_string(index) + "]";
        const Codec codec = readCodec(list[index], file, at);
        if (codec.name == "transpose" && !toBytes) {
            requireIdentityTranspose(codec, array.shape.size(), file, at);
        } else if ((codec.name == "bytes" || codec.name == "endian") && !toBytes) {
            array.byteOrder = readEndian(codec, array, file, at);
            toBytes = true;
        } else if (codec.name == "sharding_indexed" && !toBytes && allowSharding) {
            readShardingConfiguration(codec, file, at, array);
            toBytes = true;
        } else if (const auto byteCodec = byteCodecNamed(codec.name); byteCodec && toBytes) {
            if (array.sharding && allowSharding)
                throwInputError(file, at, "a codec applied to whole shards is not supported");
            if (isCompressor(*byteCodec) && ++compressors > 1)
                throwInputError(file, at, "a second compressor in one chain is not supported");
            array.codecs.push_back(*byteCodec);
        } else {
            throwInputError(file, at, "\"" + codec.name + "\" is not a codec this reader knows here (known: transpose, "
                                      "bytes, sharding_indexed, then blosc, gzip, zstd, crc32c)");
        }
    }
    if (!toBytes) throwInputError(file, field, "has no array-to-bytes codec (\"bytes\" or \"sharding_indexed\")");
}

// The index is 16 bytes per inner chunk, little-endian, optionally followed by a CRC-32C.
void readIndexCodecs(const nlohmann::json& list, const std::filesystem::path& file, const std::string& field,
                     ZarrSharding& sharding) {
    if (!list.is_array() || list.empty()) throwInputError(file, field, "must be a non-empty list of codecs");
    const Codec first = readCodec(list[0], file, field + "[0]");
    if (first.name != "bytes" || first.configuration.value("endian", "little") != "little")
        throwInputError(file, field + "[0]", "the shard index must be \"bytes\" with little endian");
    if (list.size() == 2 && readCodec(list[1], file, field + "[1]").name == "crc32c")
        sharding.indexChecksummed = true;
    else if (list.size() != 1)
        throwInputError(file, field, "only \"bytes\" and an optional \"crc32c\" are supported for the shard index");
}

void readShardingConfiguration(const Codec& codec, const std::filesystem::path& file, const std::string& field,
                               ZarrArray& array) {
    const std::string configuration = field + ".configuration";
    ZarrSharding sharding;
    sharding.shardShape = array.chunkShape;
    array.chunkShape = JsonField(file, codec.configuration, configuration).member("chunk_shape").wholeNumbers(1);
    if (array.chunkShape.size() != sharding.shardShape.size())
        throwInputError(file, configuration + ".chunk_shape", "has another number of dimensions than the shards");
    for (std::size_t axis = 0; axis < array.chunkShape.size(); ++axis)
        if (sharding.shardShape[axis] % array.chunkShape[axis] != 0)
            throwInputError(file, configuration + ".chunk_shape",
                            "does not divide the shard shape along dimension " + std::to_string(axis));
    const std::string location = codec.configuration.value("index_location", "end");
    if (location != "start" && location != "end")
        throwInputError(file, configuration + ".index_location", "is \"" + location + "\", not \"start\" or \"end\"");
    sharding.indexAtEnd = location == "end";
    readIndexCodecs(JsonField(file, codec.configuration, configuration).member("index_codecs").value(), file,
                    configuration + ".index_codecs", sharding);
    array.sharding = sharding;
    readCodecList(JsonField(file, codec.configuration, configuration).member("codecs").value(), file, configuration + ".codecs", false,
                  array);
}

}  // namespace

void readCodecPipeline(const nlohmann::json& codecs, const std::filesystem::path& file, ZarrArray& array) {
    readCodecList(codecs, file, "codecs", true, array);
}

}  // namespace tstyles
