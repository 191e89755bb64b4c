// Fuzz target: a NetCDF file through the reader. Classic files (CDF-1, CDF-2, CDF-5) are read in
// this process: the reader checks their header against the file (netcdf_classic_check.h) before
// nc_open reads it. NetCDF-4 (HDF5) files are read as the program reads them, in a reader process
// (isolated_reading.h): libhdf5 crashes and hangs on damaged files (issue 38), which the program
// survives and reports as an InputError; so does this target. Other inputs are left out.
#include <chrono>

#include "fuzz_series_file.h"
#include "netcdf_classic_check.h"
#include "tstyles/data/isolated_reading.h"

namespace {

bool hasHdf5Magic(const std::uint8_t* data, std::size_t size) {
    return size >= 8 && data[0] == 0x89 && data[1] == 'H' && data[2] == 'D' && data[3] == 'F';
}

// The program's rule (isolated_reading.h) with a shorter silence, under libFuzzer's -timeout=10.
void readNetcdf4Isolated(std::string_view bytes) {
    const auto file = tstyles_fuzz::writeScratchFile("input.nc", bytes);
    tstyles::ReadOptions options;
    options.maxMemoryBytes = tstyles_fuzz::kMemoryCap;
    tstyles::IsolationLimits limits;
    limits.silence = std::chrono::milliseconds(3000);
    limits.memoryBytes = std::uint64_t(256) << 20;
    tstyles_fuzz::expectInputErrorAtMost([&] {
        tstyles::readIsolated(
            file,
            [&](tstyles::ReadingMonitor& monitor) {
                options.monitor = &monitor;
                return tstyles::openSeries(file, options);
            },
            limits);
    });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (hasHdf5Magic(data, size)) {
        readNetcdf4Isolated(tstyles_fuzz::asText(data, size));
        return 0;
    }
    if (size < 4 || data[0] != 'C' || data[1] != 'D' || data[2] != 'F') return -1;  // not added to the corpus
    tstyles_fuzz::openSeriesFile("input.nc", tstyles_fuzz::asText(data, size));
    return 0;
}
