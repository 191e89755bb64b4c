// Isabel raw files: names give variable and hour; every file must have the same variable and size.
#include "isabel_reader.h"

#include <algorithm>
#include <regex>

#include "../value_decoding.h"
#include "file_bytes.h"
#include "finite_values.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

// The contest's files: 500 x 500 x 100 samples.
constexpr glm::ivec3 kIsabelDims{500, 500, 100};
// Land and points below ground hold 1.0e35; anything this large is that marker.
constexpr float kMissingThreshold = 0.99e35f;

const std::regex& isabelName() {
    static const std::regex pattern(R"(([A-Za-z]+)f([0-9]{1,3})\.bin(\.gz)?)");
    return pattern;
}

struct IsabelFile {
    std::filesystem::path path;
    std::string variable;
    int hour = 0;
    bool gzip = false;
};

IsabelFile describe(const std::filesystem::path& path) {
    std::smatch match;
    const std::string name = path.filename().string();
    if (!std::regex_match(name, match, isabelName()))
        throwInputError(path, "", "not named like a Hurricane Isabel file (VARIABLEfHH.bin or .bin.gz, e.g. QCLOUDf01.bin)");
    return {path, match[1], std::stoi(match[2]), match[3].matched || isGzipFile(path)};
}

}  // namespace

bool isIsabelFileName(const std::filesystem::path& file) {
    return std::regex_match(file.filename().string(), isabelName());
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
        const std::string layout = std::to_string(gridDims.x) + " x " + std::to_string(gridDims.y) + " x " +
                                   std::to_string(gridDims.z) + " big-endian float32 values";
        if (!file.gzip) {
            const std::uintmax_t size = std::filesystem::file_size(file.path);
            if (size != count * 4)
                throwInputError(file.path, "",
                                std::string(size < count * 4 ? "is truncated" : "is too large") + ": expected " +
                                    std::to_string(count * 4) + " bytes (" + layout + "), found " +
                                    std::to_string(size) + " (files of another size need --dims NXxNYxNZ)");
        }
        const auto bytes = readDataBytes(file.path, 0, count * 4, file.gzip ? DataEncoding::Gzip : DataEncoding::Raw, layout);
        std::vector<float> values = decodeValues(bytes.data(), count, ValueType::Float32, ByteOrder::Big);
        // NaN or Inf was never a marker: only 1.0e35 is (and it is finite), so check first.
        requireFiniteValues(values, gridDims, file.path, index, "only 1.0e35 marks missing data in these files");
        for (float& value : values)
            if (value >= kMissingThreshold) value = missingDensity();
        return values;
    };
    return source;
}

}  // namespace tstyles
