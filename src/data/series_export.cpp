// Raw series to manifest folders, all or nothing.
#include "tstyles/data/series_export.h"

#include <bit>
#include <cstdint>
#include <string>
#include <system_error>

#include <unistd.h>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace tstyles {
namespace {

std::vector<std::uint8_t> littleEndianFloats(const std::vector<float>& values) {
    std::vector<std::uint8_t> bytes;
    bytes.reserve(values.size() * 4);
    for (const float value : values) {
        const auto bits = std::bit_cast<std::uint32_t>(value);
        for (int shift = 0; shift < 32; shift += 8) bytes.push_back(std::uint8_t(bits >> shift));
    }
    return bytes;
}

bool isNonEmptyFolder(const std::filesystem::path& folder) {
    std::error_code error;
    return std::filesystem::is_directory(folder, error) && !std::filesystem::is_empty(folder, error);
}

void requireReplaceable(const std::filesystem::path& directory, bool overwrite) {
    userPathKind(PathSource{}, directory);  // a name the system refuses is named here, not "cannot make"
    std::error_code error;
    if (std::filesystem::exists(directory, error) && !std::filesystem::is_directory(directory, error))
        throwInputError(directory, "", "exists and is not a folder: the output of convert is a dataset folder");
    if (!overwrite && isNonEmptyFolder(directory))
        throwInputError(directory, "", "is a folder that is not empty: choose another, or add --force to replace it");
}

// ".NAME.tmpPID" beside the target, so that the rename stays on one file system.
std::filesystem::path temporaryFolderFor(const std::filesystem::path& directory, const std::string& purpose) {
    const std::filesystem::path absolute = std::filesystem::absolute(directory).lexically_normal();
    const std::filesystem::path target = absolute.has_filename() ? absolute : absolute.parent_path();
    return target.parent_path() / ("." + target.filename().string() + "." + purpose + ".tmp" + std::to_string(getpid()));
}

// Removes the folder when it goes out of scope, unless released.
class FolderGuard {
public:
    explicit FolderGuard(std::filesystem::path folder) : folder_(std::move(folder)) {}
    FolderGuard(const FolderGuard&) = delete;
    FolderGuard& operator=(const FolderGuard&) = delete;
    ~FolderGuard() {
        std::error_code error;
        if (!folder_.empty()) std::filesystem::remove_all(folder_, error);
    }
    void release() { folder_.clear(); }

private:
    std::filesystem::path folder_;
};

}  // namespace

RawSeries toRawSeries(const Series& rawValues, const std::filesystem::path& source) {
    RawSeries raw;
    raw.name = rawValues.name;
    raw.valueRange = rawValues.valueRange;
    raw.axes = rawValues.axes;
    raw.time = rawValues.time;
    bool missing = false;
    for (std::size_t index = 0; index < rawValues.size(); ++index) {
        const TimeStep& step = rawValues.steps[index];
        if (index > 0 && !(step.time > rawValues.steps[index - 1].time))
            throwInputError(source, "",
                            "time-step " + std::to_string(index) + " has time " + std::to_string(step.time) +
                                ", not after the one before it (" + std::to_string(rawValues.steps[index - 1].time) +
                                "): a manifest needs increasing times");
        RawTimeStep out;
        out.time = step.time;
        if (const StructuredGrid* structured = step.structured()) out.structured = *structured;
        else out.grid = step.rectilinear();
        out.placement = step.placement;
        out.type = ValueType::Float32;
        out.bytes = littleEndianFloats(step.density);
        out.mask = step.mask;
        for (const float value : step.density) missing = missing || isMissing(value);
        raw.steps.push_back(std::move(out));
    }
    if (missing) raw.missingValue = std::nan("");
    return raw;
}

void writeSeriesFolder(const RawSeries& series, const std::filesystem::path& directory, bool overwrite) {
    requireReplaceable(directory, overwrite);
    const std::filesystem::path fresh = temporaryFolderFor(directory, "new");
    std::error_code error;
    std::filesystem::remove_all(fresh, error);
    FolderGuard freshGuard(fresh);
    writeSeries(series, fresh);

    requireReplaceable(directory, overwrite);  // again: it may have changed while we wrote
    const std::filesystem::path old = temporaryFolderFor(directory, "old");
    FolderGuard oldGuard(old);
    if (std::filesystem::exists(directory, error)) {
        std::filesystem::rename(directory, old, error);
        if (error) throwInputError(directory, "", "cannot be replaced: " + error.message());
    }
    std::filesystem::rename(fresh, directory, error);
    if (error) {
        std::error_code restore;
        if (std::filesystem::exists(old, restore)) std::filesystem::rename(old, directory, restore);
        throwInputError(directory, "", "cannot be written: " + error.message());
    }
    freshGuard.release();
}

}  // namespace tstyles
