// The fuzz targets of the readers behind openSeries (NRRD, NetCDF, NIfTI, Isabel): the input
// becomes one file with the format's name, opened with the fuzz memory cap, every time-step read
// and mapped to density as `tstyles render` does.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include <chrono>

#include "fuzz_support.h"
#include "tstyles/data/isolated_reading.h"
#include "tstyles/data/read_options.h"
#include "tstyles/data/series_opener.h"

namespace tstyles_fuzz {

inline void openSeriesFile(const std::string& name, std::string_view bytes, tstyles::ReadOptions options = {}) {
    const auto file = writeScratchFile(name, bytes);
    options.maxMemoryBytes = kMemoryCap;
    expectInputErrorAtMost([&] { tstyles::openSeries(file, options); });
}

// As openSeriesFile, but in a reader process, as the program reads (isolated_reading.h): for the
// formats whose library crashes or hangs on damaged files (libhdf5, GDCM; issue 38), which the
// program survives and reports as an InputError, and so does the target. The program's rule with a
// shorter silence, under libFuzzer's -timeout=10. Coverage inside the child does not reach
// libFuzzer: these inputs are mutated blind.
inline void openSeriesFileIsolated(const std::string& name, std::string_view bytes) {
    const auto file = writeScratchFile(name, bytes);
    tstyles::ReadOptions options;
    options.maxMemoryBytes = kMemoryCap;
    tstyles::IsolationLimits limits;
    limits.silence = std::chrono::milliseconds(3000);
    limits.memoryBytes = std::uint64_t(256) << 20;
    expectInputErrorAtMost([&] {
        tstyles::readIsolated(
            file,
            [&](tstyles::ReadingMonitor& monitor) {
                options.monitor = &monitor;
                return tstyles::openSeries(file, options);
            },
            limits);
    });
}

}  // namespace tstyles_fuzz
