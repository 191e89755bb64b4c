// The front ends' way to open a dataset: openSeries in a reader process, with limits that grow
// with the input's size (isolated_reading.h).
#include <cstdlib>
#include <cstring>

#include "tstyles/core/input_limits.h"
#include "tstyles/data/isolated_reading.h"
#include "tstyles/data/series_opener.h"

namespace tstyles {
namespace {

// 30 s: a hang in a library (libhdf5 loops for good on some damaged files) ends in half a minute,
// while a healthy file on a loaded machine or slow storage has room between two signs of progress.
// Under AddressSanitizer the reader runs several times slower (a CI stage measured a small
// manifest silent for over 10 s), so the deadline is four times as long there.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kSanitizerSlowdown = 4;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int kSanitizerSlowdown = 4;
#else
constexpr int kSanitizerSlowdown = 1;
#endif
#else
constexpr int kSanitizerSlowdown = 1;
#endif
constexpr std::chrono::milliseconds kSilenceBase{30'000 * kSanitizerSlowdown};
constexpr double kBytesPerSilentSecond = 50.0 * 1024.0 * 1024.0;
constexpr std::uint64_t kLibraryHeadroom = std::uint64_t(1) << 30;
// A folder (a manifest's, a DICOM series) is measured up to this many entries: enough for the
// deadline's rule, and quick on a folder of millions of files.
constexpr std::size_t kMaxEntriesMeasured = 100'000;

std::uint64_t folderBytes(const std::filesystem::path& folder) {
    std::uint64_t total = 0;
    std::size_t entries = 0;
    std::error_code error;
    for (std::filesystem::recursive_directory_iterator it(folder, error), end; !error && it != end;
         it.increment(error)) {
        if (++entries > kMaxEntriesMeasured) break;
        std::error_code sizeError;
        if (it->is_regular_file(sizeError)) total += it->file_size(sizeError);
    }
    return total;
}

// What the inputs hold: files, folders read whole, and a manifest's folder (its value files).
std::uint64_t inputBytes(const std::vector<std::filesystem::path>& inputs) {
    std::uint64_t total = 0;
    for (const auto& input : inputs) {
        std::error_code error;
        if (std::filesystem::is_directory(input, error)) {
            total += folderBytes(input);
        } else if (isManifestInput(input)) {
            total += folderBytes(input.parent_path().empty() ? "." : input.parent_path());
        } else if (std::filesystem::is_regular_file(input, error)) {
            total += std::filesystem::file_size(input, error);
        }
    }
    return total;
}

Series openThroughReader(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options,
                         Series (*open)(const std::vector<std::filesystem::path>&, const ReadOptions&)) {
    if (inputs.empty() || readingInProcessRequested()) return open(inputs, options);
    return readIsolated(
        inputs.front(),
        [&](ReadingMonitor& monitor) {
            ReadOptions monitored = options;
            monitored.monitor = &monitor;
            return open(inputs, monitored);
        },
        isolationLimitsFor(inputs, options));
}

}  // namespace

IsolationLimits isolationLimitsFor(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options) {
    std::vector<std::filesystem::path> all = inputs;
    all.insert(all.end(), options.solutionFiles.begin(), options.solutionFiles.end());
    IsolationLimits limits;
    limits.silence = kSilenceBase + std::chrono::milliseconds(std::int64_t(
                                        1000.0 * kSanitizerSlowdown * double(inputBytes(all)) / kBytesPerSilentSecond));
    limits.memoryBytes = 2 * memoryCap(options.maxMemoryBytes) + kLibraryHeadroom;
    return limits;
}

bool readingInProcessRequested() {
    const char* value = std::getenv("TSTYLES_READ_IN_PROCESS");
    return value != nullptr && std::strcmp(value, "1") == 0;
}

Series openSeriesIsolated(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options) {
    return openThroughReader(inputs, options, &openSeries);
}

Series openRawSeriesIsolated(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options) {
    return openThroughReader(inputs, options, &openRawSeries);
}

}  // namespace tstyles
