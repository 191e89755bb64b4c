// Fuzz target: a classic NetCDF file (CDF-1, CDF-2, CDF-5) through the reader, which checks the
// header against the file (netcdf_classic_check.h) before nc_open reads it. Inputs without the
// classic magic are left out: HDF5 (netCDF-4) is the HDF5 library's own parser.
#include "fuzz_series_file.h"
#include "netcdf_classic_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 4 || data[0] != 'C' || data[1] != 'D' || data[2] != 'F') return -1;  // not added to the corpus
    tstyles_fuzz::openSeriesFile("input.nc", tstyles_fuzz::asText(data, size));
    return 0;
}
