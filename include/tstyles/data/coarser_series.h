// A series at a lower resolution: what a GPU memory budget uploads when the full one does not fit.
// Same extent, time-steps, placements and value range; fewer samples. GL-free.
#pragma once

#include "tstyles/data/series.h"

namespace tstyles {

// Whether every time-step can be resampled (rectilinear grids, even or uneven axes).
bool canCoarsen(const Series& series);

// The dims of a time-step of `dims` read `scale` times coarser along each axis (scale >= 1): at
// least 2 samples, never more than it has.
glm::ivec3 coarserDims(glm::ivec3 dims, double scale);

// Every time-step resampled to coarserDims over the same extent: densities trilinearly (missing
// values stay missing where they carry half the weight, as --resample does), masks from the nearest
// sample. The series must be coarsenable (canCoarsen).
Series coarserSeries(const Series& series, double scale);

}  // namespace tstyles
