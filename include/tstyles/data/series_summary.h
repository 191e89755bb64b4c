// What `tstyles info DATASET` prints about a loaded series, and the numbers behind it: alignment,
// overlap between adjacent time-steps, and memory on disk and on the GPU.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

// A readable multi-line description: name, manifest, time-steps, value range, alignment, one table
// row per time-step, overlap of adjacent time-steps and memory.
std::string describeSeries(const Series& series);

// True when every time-step has the same grid (kind, dims, spacing) and the same placement, so one
// entry/exit buffer pair serves them all.
bool isFullyAligned(const Series& series);

// The fraction in [0, 1] of the smaller of the two time-steps' world boxes that lies inside both.
// 1 when one box contains the other, 0 when they are apart or only touch.
double overlapFraction(const Series& series, std::size_t a, std::size_t b);

// Bytes of the raw value, mask and coordinates files (the manifest itself not counted).
std::size_t diskBytes(const Series& series);

// Bytes the renderer uploads: 2 per voxel for density as 16-bit, plus 1 per mask voxel, plus the
// inverse maps of structured grids.
std::size_t gpuBytes(const Series& series);

// The structured grids of the series, each once however many time-steps share it.
std::vector<const StructuredGrid*> distinctStructuredGrids(const Series& series);
// Bytes of their inverse maps (RGBA32F), shared by the time-steps on one grid.
std::size_t inverseMapBytes(const Series& series);

}  // namespace tstyles
