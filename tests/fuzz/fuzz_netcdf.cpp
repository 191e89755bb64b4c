// Fuzz target: a NetCDF file through the reader. Classic files (CDF-1, CDF-2, CDF-5) are read in
// this process: the reader checks their header against the file (netcdf_classic_check.h) before
// nc_open reads it. NetCDF-4 (HDF5) files are read as the program reads them, in a reader process
// (isolated_reading.h): libhdf5 crashes and hangs on damaged files (issue 38), which the program
// survives and reports as an InputError; so does this target. Other inputs are left out.
#include "fuzz_series_file.h"

namespace {

bool hasHdf5Magic(const std::uint8_t* data, std::size_t size) {
    return size >= 8 && data[0] == 0x89 && data[1] == 'H' && data[2] == 'D' && data[3] == 'F';
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (hasHdf5Magic(data, size)) {
        tstyles_fuzz::openSeriesFileIsolated("input.nc", tstyles_fuzz::asText(data, size));
        return 0;
    }
    if (size < 4 || data[0] != 'C' || data[1] != 'D' || data[2] != 'F') return -1;  // not added to the corpus
    tstyles_fuzz::openSeriesFile("input.nc", tstyles_fuzz::asText(data, size));
    return 0;
}
