// Isabel raw files: names give variable and hour; every file must have the same variable and size.
#include "isabel_reader.h"

#include <algorithm>
#include <cctype>
#include <optional>

#include "../../value_decoding.h"
#include "../file_bytes.h"
#include "../infinite_values.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

// The contest's files: 500 x 500 x 100 samples.
constexpr glm::ivec3 kIsabelDims{500, 500, 100};
// Land and points below ground hold 1.0e35; anything this large is that marker.
constexpr float kMissingThreshold = 0.99e35f;

struct IsabelName {
    std::string variable;
    int hour = 0;
    bool gzipSuffix = false;
};

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// VARIABLEfHH.bin or VARIABLEfHH.bin.gz: letters, "f", one to three digits.
std::optional<IsabelName> parseIsabelName(std::string name) {
    IsabelName parsed;
    parsed.gzipSuffix = endsWith(name, ".gz");
    if (parsed.gzipSuffix) name.resize(name.size() - 3);
    if (!endsWith(name, ".bin")) return std::nullopt;
    name.resize(name.size() - 4);
    std::size_t digits = 0;
    while (digits < name.size() && std::isdigit(static_cast<unsigned char>(name[name.size() - 1 - digits]))) ++digits;
    if (digits == 0 || digits > 3 || name.size() < digits + 2 || name[name.size() - digits - 1] != 'f') return std::nullopt;
    parsed.variable = name.substr(0, name.size() - digits - 1);
    for (char c : parsed.variable)
        if (!std::isalpha(static_cast<unsigned char>(c))) return std::nullopt;
    parsed.hour = std::stoi(name.substr(name.size() - digits));
    return parsed;
}

struct IsabelFile {
    std::filesystem::path path;
    std::string variable;
    int hour = 0;
    bool gzip = false;
};

IsabelFile describe(const std::filesystem::path& path) {
    const auto name = parseIsabelName(path.filename().string());
    if (!name)
        throwInputError(path, "", "not named like a Hurricane Isabel file (VARIABLEfHH.bin or .bin.gz, e.g. QCLOUDf01.bin)");
    return {path, name->variable, name->hour, name->gzipSuffix || isGzipFile(path)};
}

std::string layoutText(const glm::ivec3& dims) {
    return std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " + std::to_string(dims.z) +
           " big-endian float32 values";
}

// Every file holds one volume: a raw file exactly its bytes, a gzip file at least enough
// compressed bytes for them (the exact count is known once inflated). Checked on opening, before
// memory is planned for data that is not there.
void checkSize(const IsabelFile& file, const glm::ivec3& dims) {
    const std::uint64_t expected = std::uint64_t(dims.x) * std::uint64_t(dims.y) * std::uint64_t(dims.z) * 4;
    if (file.gzip) return requireDataInFile(file.path, 0, double(expected), DataEncoding::Gzip, layoutText(dims));
    const std::uint64_t size = regularFileSize(file.path, "Hurricane Isabel file");
    if (size != expected)
        throwInputError(file.path, "",
                        std::string(size < expected ? "is truncated" : "is too large") + ": expected " +
                            std::to_string(expected) + " bytes (" + layoutText(dims) + "), found " +
                            std::to_string(size) + " (files of another size need --dims NXxNYxNZ)");
}

}  // namespace

bool isIsabelFileName(const std::filesystem::path& file) {
    return parseIsabelName(file.filename().string()).has_value();
}

SourceSeries openIsabel(const std::vector<std::filesystem::path>& paths, const std::optional<glm::ivec3>& dims) {
    std::vector<IsabelFile> files;
    for (const auto& path : paths) files.push_back(describe(path));
    std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.hour < b.hour; });
    for (std::size_t index = 1; index < files.size(); ++index) {
        if (files[index].variable != files[0].variable)
            throwInputError(files[index].path, "",
                            "holds variable " + files[index].variable + " but " + files[0].path.filename().string() +
                                " holds " + files[0].variable + ": give the files of one variable");
        if (files[index].hour == files[index - 1].hour)
            throwInputError(files[index].path, "",
                            "is hour " + std::to_string(files[index].hour) + " like " + files[index - 1].path.string());
    }
    const glm::ivec3 gridDims = dims.value_or(kIsabelDims);

    SourceSeries source;
    source.name = "Hurricane Isabel " + files[0].variable;
    source.file = files[0].path;
    source.format = "Hurricane Isabel raw";
    for (const IsabelFile& file : files) {
        checkSize(file, gridDims);
        SourceStep step;
        step.time = double(file.hour);
        RectilinearGrid grid;
        grid.dims = gridDims;
        // One unit per original sample along every axis: the contest renderings' aspect (the
        // true 2000 km by 2000 km by 20 km box would be a sheet).
        grid.spacing = glm::dvec3(1.0);
        step.grid = grid;
        step.type = ValueType::Float32;
        step.file = file.path;
        source.steps.push_back(step);
    }
    source.readStep = [files, gridDims](std::size_t index) {
        const IsabelFile& file = files[index];
        const std::size_t count = std::size_t(gridDims.x) * std::size_t(gridDims.y) * std::size_t(gridDims.z);
        const std::string layout = layoutText(gridDims);
        // A gzip file must hold exactly one volume too: more means --dims does not match the file.
        const auto bytes = readDataBytes(file.path, 0, count * 4, file.gzip ? DataEncoding::Gzip : DataEncoding::Raw,
                                         layout, TrailingData::Refused);
        std::vector<float> values = decodeValues(bytes.data(), count, ValueType::Float32, ByteOrder::Big);
        // An infinity was never a marker (1.0e35 is, and it is finite); NaN is missing in every format.
        refuseInfinities(values, gridDims, file.path, index);
        for (float& value : values)
            if (value >= kMissingThreshold) value = missingDensity();
        return values;
    };
    return source;
}

}  // namespace tstyles
