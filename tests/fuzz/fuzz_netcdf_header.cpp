// Fuzz target: our check of a classic NetCDF header against the file's size alone (the part that
// must hold before nc_open may see a file), many times faster than the whole reader.
#include "fuzz_support.h"
#include "netcdf/netcdf_classic_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = tstyles_fuzz::writeScratchFile("input.nc", tstyles_fuzz::asText(data, size));
    tstyles_fuzz::expectInputErrorAtMost([&] { tstyles::checkClassicNetcdf(file); });
    return 0;
}
