// Our own check of a classic NetCDF header (CDF-1, 64-bit offset CDF-2, 64-bit data CDF-5) against
// the file's size, before libnetcdf trusts it: a header whose counts or sizes exceed the file can
// make nc_open allocate gigabytes or spin for minutes, and a cut file reads as fill values.
#pragma once

#include <filesystem>

namespace tstyles {

// True when the file starts with a classic NetCDF magic ("CDF" 1, 2 or 5).
bool hasClassicNetcdfMagic(const std::filesystem::path& file);

// Walks the header with every count and length bounded by the bytes left in the file, then checks
// that each variable's data (every record of the record variables) lies inside the file. A
// shortfall is an InputError that says "truncated" and names the variable, the record (time-step)
// and the expected and actual byte counts; a header that cannot be a NetCDF header says "damaged".
void checkClassicNetcdf(const std::filesystem::path& file);

}  // namespace tstyles
