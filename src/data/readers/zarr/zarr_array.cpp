// Zarr v2 `.zarray` and v3 `zarr.json` array metadata to one ZarrArray; the v3 codec pipeline
// (transpose, bytes or sharding_indexed, compressors, crc32c) in zarr_codec_pipeline.cpp.
#include "zarr_array.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "tstyles/core/errors.h"
#include "tstyles/core/json_field.h"
#include "tstyles/core/input_limits.h"
#include "zarr_codec_pipeline.h"
#include "zarr_json.h"

namespace tstyles {
namespace {

const char* const kReadableTypes = "bool, int8, uint8, int16, uint16, int32, float32 and float64";

// numpy's spelling in v2 ("<u2", ">f4", "|u1", "|b1"): byte order, kind, size.
void readV2DataType(const nlohmann::json& value, const std::filesystem::path& file, ZarrArray& array) {
    if (!value.is_string())
        throwInputError(file, "dtype", "must be a string such as \"<u2\"; structured types (" + value.dump() +
                                           ") are not supported");
    const std::string text = value.get<std::string>();
    array.dataTypeText = text;
    struct Known { const char* body; ValueType type; };
    static constexpr Known kKnown[] = {{"b1", ValueType::UInt8}, {"u1", ValueType::UInt8},  {"i1", ValueType::Int8},
                                       {"u2", ValueType::UInt16}, {"i2", ValueType::Int16}, {"i4", ValueType::Int32},
                                       {"f4", ValueType::Float32}, {"f8", ValueType::Float64}};
    if (text.size() >= 2 && (text[0] == '<' || text[0] == '>' || text[0] == '|'))
        for (const Known& known : kKnown)
            if (text.substr(1) == known.body) {
                array.type = known.type;
                array.byteOrder = text[0] == '>' ? ByteOrder::Big : ByteOrder::Little;
                return;
            }
    throwInputError(file, "dtype", "\"" + text + "\" is not a data type this reader stores (readable: " +
                                       std::string(kReadableTypes) + ", as \"<u2\", \">f4\", \"|u1\")");
}

ValueType v3DataType(const std::string& name, const std::filesystem::path& file) {
    struct Known { const char* name; ValueType type; };
    static constexpr Known kKnown[] = {{"bool", ValueType::UInt8},     {"uint8", ValueType::UInt8},
                                       {"int8", ValueType::Int8},     {"uint16", ValueType::UInt16},
                                       {"int16", ValueType::Int16},   {"int32", ValueType::Int32},
                                       {"float32", ValueType::Float32}, {"float64", ValueType::Float64}};
    for (const Known& known : kKnown)
        if (name == known.name) return known.type;
    throwInputError(file, "data_type", "\"" + name + "\" is not a data type this reader stores (readable: " +
                                           std::string(kReadableTypes) + ")");
}

// Numbers, "NaN", "Infinity", "-Infinity", booleans; v3 also a float's bits in hex ("0x7fc00000");
// null (v2: no fill value) reads as 0.
double readFillValue(const nlohmann::json& value, const ZarrArray& array, const std::filesystem::path& file) {
    const bool isFloat = array.type == ValueType::Float32 || array.type == ValueType::Float64;
    if (value.is_null()) return 0.0;
    if (value.is_boolean()) return value.get<bool>() ? 1.0 : 0.0;
    if (value.is_number()) return value.get<double>();
    if (value.is_string() && isFloat) {
        const std::string text = value.get<std::string>();
        if (text == "NaN") return std::numeric_limits<double>::quiet_NaN();
        if (text == "Infinity") return std::numeric_limits<double>::infinity();
        if (text == "-Infinity") return -std::numeric_limits<double>::infinity();
        if (text.size() == 10 && text.rfind("0x", 0) == 0 && array.type == ValueType::Float32) {
            std::uint32_t bits = 0;
            const auto [end, problem] = std::from_chars(text.data() + 2, text.data() + text.size(), bits, 16);
            if (problem == std::errc() && end == text.data() + text.size()) {
                float number;
                std::memcpy(&number, &bits, sizeof number);
                return number;
            }
        }
    }
    throwInputError(file, "fill_value", value.dump() + " is not a fill value of a " + array.dataTypeText + " array");
}

void requireKnownKeys(const nlohmann::json& json, const std::set<std::string>& known, const std::filesystem::path& file) {
    for (const auto& [key, value] : json.items()) {
        if (known.count(key)) continue;
        // v3 lets extensions add keys that a reader may ignore when they say so.
        if (value.is_object() && value.value("must_understand", true) == false) continue;
        throwInputError(file, key, "is not a key of Zarr array metadata");
    }
}

void readV2Compressor(const nlohmann::json& value, const std::filesystem::path& file, ZarrArray& array) {
    if (value.is_null()) return;
    const std::string id = JsonField(file, value, "compressor").member("id").string();
    static const std::pair<const char*, ZarrByteCodec> kKnown[] = {{"blosc", ZarrByteCodec::Blosc},
                                                                   {"zlib", ZarrByteCodec::Zlib},
                                                                   {"gzip", ZarrByteCodec::Gzip},
                                                                   {"zstd", ZarrByteCodec::Zstd},
                                                                   {"lz4", ZarrByteCodec::Lz4}};
    for (const auto& [name, codec] : kKnown)
        if (id == name) {
            array.codecs.push_back(codec);
            return;
        }
    throwInputError(file, "compressor.id", "\"" + id + "\" is not a compressor this reader knows (blosc, zlib, gzip, zstd, lz4)");
}

void readV2(const nlohmann::json& json, const std::filesystem::path& file, ZarrArray& array) {
    requireKnownKeys(json, {"zarr_format", "shape", "chunks", "dtype", "compressor", "fill_value", "order", "filters",
                            "dimension_separator"},
                     file);
    const auto& format = JsonField(file, json, "").member("zarr_format").value();
    if (format != 2) throwInputError(file, "zarr_format", "is " + format.dump() + ", a .zarray file is Zarr format 2");
    array.shape = JsonField(file, json, "").member("shape").wholeNumbers(0);
    array.chunkShape = JsonField(file, json, "").member("chunks").wholeNumbers(1);
    readV2DataType(JsonField(file, json, "").member("dtype").value(), file, array);
    readV2Compressor(JsonField(file, json, "").member("compressor").value(), file, array);
    array.fillValue = readFillValue(JsonField(file, json, "").member("fill_value").value(), array, file);
    const std::string order = JsonField(file, json, "").member("order").string();
    if (order != "C" && order != "F") throwInputError(file, "order", "is \"" + order + "\", not \"C\" or \"F\"");
    array.fortranOrder = order == "F";
    const auto filters = json.find("filters");
    if (filters != json.end() && !filters->is_null() && !(filters->is_array() && filters->empty()))
        throwInputError(file, "filters", filters->dump() + ": filters (delta, shuffle, ...) are not supported; "
                                         "rewrite the array without them");
    const std::string separator = json.contains("dimension_separator")
                                      ? JsonField(file, json["dimension_separator"], "dimension_separator").string()
                                      : ".";
    if (separator != "." && separator != "/")
        throwInputError(file, "dimension_separator", "is \"" + separator + "\", not \".\" or \"/\"");
    array.keySeparator = separator[0];
}

void readV3ChunkKeys(const nlohmann::json& json, const std::filesystem::path& file, ZarrArray& array) {
    const auto& encoding = JsonField(file, json, "").member("chunk_key_encoding").value();
    const std::string name = JsonField(file, encoding, "chunk_key_encoding").member("name").string();
    if (name != "default" && name != "v2")
        throwInputError(file, "chunk_key_encoding.name", "is \"" + name + "\", not \"default\" or \"v2\"");
    array.v2ChunkKeys = name == "v2";
    std::string separator = array.v2ChunkKeys ? "." : "/";
    if (encoding.contains("configuration") && encoding["configuration"].contains("separator"))
        separator = JsonField(file, encoding["configuration"]["separator"], "chunk_key_encoding.configuration.separator").string();
    if (separator != "." && separator != "/")
        throwInputError(file, "chunk_key_encoding.configuration.separator", "is \"" + separator + "\", not \".\" or \"/\"");
    array.keySeparator = separator[0];
}

void readV3(const nlohmann::json& json, const std::filesystem::path& file, ZarrArray& array) {
    requireKnownKeys(json, {"zarr_format", "node_type", "shape", "data_type", "chunk_grid", "chunk_key_encoding",
                            "fill_value", "codecs", "attributes", "dimension_names", "storage_transformers"},
                     file);
    const auto& format = JsonField(file, json, "").member("zarr_format").value();
    if (format != 3) throwInputError(file, "zarr_format", "is " + format.dump() + ", a zarr.json file is Zarr format 3");
    const std::string node = JsonField(file, json, "").member("node_type").string();
    if (node != "array") throwInputError(file, "node_type", "is \"" + node + "\" where an array was expected");
    if (json.contains("storage_transformers") && !json["storage_transformers"].empty())
        throwInputError(file, "storage_transformers", "are not supported");
    array.shape = JsonField(file, json, "").member("shape").wholeNumbers(0);
    array.dataTypeText = JsonField(file, json, "").member("data_type").string();
    array.type = v3DataType(array.dataTypeText, file);
    const auto& grid = JsonField(file, json, "").member("chunk_grid").value();
    if (JsonField(file, grid, "chunk_grid").member("name").string() != "regular")
        throwInputError(file, "chunk_grid.name", "only a \"regular\" chunk grid is supported");
    const auto& gridConfiguration = JsonField(file, grid, "chunk_grid").member("configuration").value();
    array.chunkShape = JsonField(file, gridConfiguration, "chunk_grid.configuration").member("chunk_shape").wholeNumbers(1);
    readV3ChunkKeys(json, file, array);
    array.fillValue = readFillValue(JsonField(file, json, "").member("fill_value").value(), array, file);
    readCodecPipeline(JsonField(file, json, "").member("codecs").value(), file, array);
}

// Chunks of a size that cannot be read into memory are refused here, before any chunk is read.
void checkChunking(const std::filesystem::path& file, const ZarrArray& array, std::uint64_t memoryCap) {
    const char* field = array.zarrFormat == 2 ? "chunks" : "chunk_grid.configuration.chunk_shape";
    if (array.shape.size() != array.chunkShape.size())
        throwInputError(file, field, "has " + std::to_string(array.chunkShape.size()) + " dimensions, the shape " +
                                         std::to_string(array.shape.size()));
    if (array.sharding && array.sharding->shardShape.size() != array.shape.size())
        throwInputError(file, "codecs", "the shards' chunk_shape has " + std::to_string(array.chunkShape.size()) +
                                            " dimensions, the shape " + std::to_string(array.shape.size()));
    double bytes = double(bytesPerValue(array.type));
    for (std::uint64_t size : array.chunkShape) bytes *= double(size);
    // 1 GiB at most: deflate and LZ4 take sizes that fit 32 bits, and a stored chunk may be twice as large.
    const std::uint64_t cap = std::min<std::uint64_t>(memoryCap, std::uint64_t(1) << 30);
    requireMemory(file, field, bytes, cap, "one chunk");
}

}  // namespace

std::size_t ZarrArray::chunkValues() const {
    std::size_t values = 1;
    for (std::uint64_t size : chunkShape) values *= std::size_t(size);
    return values;
}

ZarrArray readZarrArray(const std::filesystem::path& folder, int zarrFormat, std::uint64_t memoryCap) {
    ZarrArray array;
    array.folder = folder;
    array.zarrFormat = zarrFormat;
    array.metadataFile = folder / (zarrFormat == 2 ? ".zarray" : "zarr.json");
    std::error_code error;
    if (!std::filesystem::exists(array.metadataFile, error))
        throwInputError(array.metadataFile, "", "is missing: the multiscales name this level, but it holds no Zarr array");
    const nlohmann::json json = readZarrJson(array.metadataFile);
    try {
        if (zarrFormat == 2)
            readV2(json, array.metadataFile, array);
        else
            readV3(json, array.metadataFile, array);
    } catch (const nlohmann::json::exception& problem) {
        throwInputError(array.metadataFile, "", std::string("holds a value of the wrong kind: ") + problem.what());
    }
    checkChunking(array.metadataFile, array, memoryCap);
    return array;
}

}  // namespace tstyles
