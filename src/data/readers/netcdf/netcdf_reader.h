// NetCDF files (classic and netCDF-4, through libnetcdf): one variable of three spatial dimensions
// and an optional time dimension becomes a series, one time-step per time index. Coordinate
// variables place the grid (uneven levels included); _FillValue, missing_value, scale_factor and
// add_offset are honoured.
#pragma once

#include <filesystem>

#include "../source_series.h"
#include "tstyles/data/read_options.h"

namespace tstyles {

// Uses options.variable, options.timeDimension and options.indexAxes.
SourceSeries openNetcdf(const std::filesystem::path& file, const ReadOptions& options);

// True when the file starts with a NetCDF classic ("CDF\1", "CDF\2", "CDF\5") or HDF5 signature.
bool hasNetcdfSignature(const std::filesystem::path& file);

}  // namespace tstyles
