// Reading a file the user gave us where a crash or a hang cannot take the program down: a forked
// reader process parses the file (through the libraries beneath our readers: libnetcdf/libhdf5,
// libnifti, zlib) and hands the series back through shared memory. A reader that dies, stops making
// progress, or runs past its memory becomes one InputError naming the file, the library and the
// stage; an error the reader throws comes back as the same error. docs/readers.md, "How reading
// is isolated".
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include "tstyles/data/read_options.h"
#include "tstyles/data/reading_monitor.h"
#include "tstyles/data/series.h"

namespace tstyles {

struct IsolationLimits {
    // How long the reader may go without a sign of progress (a new stage, a time-step read).
    std::chrono::milliseconds silence{10'000};
    // The memory the reader may allocate beyond what the process held when it started; none: no
    // limit (sanitizer builds, whose shadow memory such a limit would break, ignore it too).
    std::optional<std::uint64_t> memoryBytes;
};

// The limits for reading these inputs: silence 30 s plus 1 s per 50 MiB of input (a time-step
// read is progress, so only the longest step has to fit), memory twice the --max-memory cap (or
// the default cap) plus 1 GiB for the libraries' own buffers.
IsolationLimits isolationLimitsFor(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options);

// Runs `read` in a child process and returns its series, bit for bit. `file` names the input in
// messages where the reader named no file of its own.
using IsolatedRead = std::function<Series(ReadingMonitor& monitor)>;
Series readIsolated(const std::filesystem::path& file, const IsolatedRead& read, const IsolationLimits& limits);

// The general form, for results other than a series (a style image): `work` runs in the child and
// writes its result to `resultFd` (shared memory), returning the bytes written; the parent gets
// that memory back to read with pread. Failures as for readIsolated.
using IsolatedWork = std::function<std::uint64_t(ReadingMonitor& monitor, int resultFd)>;
class IsolatedResult {
public:
    IsolatedResult(int fd, std::uint64_t bytes) : fd_(fd), bytes_(bytes) {}
    ~IsolatedResult();
    IsolatedResult(const IsolatedResult&) = delete;
    IsolatedResult& operator=(const IsolatedResult&) = delete;
    int fd() const { return fd_; }
    std::uint64_t bytes() const { return bytes_; }

private:
    int fd_;
    std::uint64_t bytes_;
};
IsolatedResult runIsolated(const std::filesystem::path& file, const IsolatedWork& work, const IsolationLimits& limits);

// True when the environment asks for reading in this process (TSTYLES_READ_IN_PROCESS=1): for
// debugging a reader, and for measuring what isolation costs.
bool readingInProcessRequested();

// openSeries and openRawSeries (series_opener.h) through readIsolated, unless reading in-process
// is requested. What every front end uses for the user's datasets.
Series openSeriesIsolated(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options);
Series openRawSeriesIsolated(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options);

}  // namespace tstyles
