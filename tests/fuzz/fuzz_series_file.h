// The fuzz targets of the readers behind openSeries (NRRD, NetCDF, NIfTI, Isabel): the input
// becomes one file with the format's name, opened with the fuzz memory cap, every time-step read
// and mapped to density as `tstyles render` does.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_support.h"
#include "tstyles/data/read_options.h"
#include "tstyles/data/series_opener.h"

namespace tstyles_fuzz {

inline void openSeriesFile(const std::string& name, std::string_view bytes, tstyles::ReadOptions options = {}) {
    const auto file = writeScratchFile(name, bytes);
    options.maxMemoryBytes = kMemoryCap;
    expectInputErrorAtMost([&] { tstyles::openSeries(file, options); });
}

}  // namespace tstyles_fuzz
