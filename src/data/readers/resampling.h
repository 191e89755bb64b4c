// Trilinear resampling of a time-step to other dims over the same extent. Missing (NaN) neighbours
// are left out of the weights; a sample is missing when missing neighbours carry half its weight or more.
#pragma once

#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

// The grid `grid` becomes at `dims`: the same extent, uneven axes keep their node spacing profile.
RectilinearGrid resampledGrid(const RectilinearGrid& grid, const glm::ivec3& dims);

std::vector<float> resampleValues(const std::vector<float>& values, const RectilinearGrid& from,
                                  const glm::ivec3& toDims);

}  // namespace tstyles
