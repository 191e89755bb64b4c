// NaN in float data is a voxel without data in every format (as napari, Fiji and ParaView show it);
// an infinity is never a value: one check, one message shape.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles {

// Throws an InputError naming the file, the time-step and the first infinite voxel's (x, y, z).
// NaN passes: it is missingDensity(), so the series counts it as missing, leaves it out of ranges
// and percentiles, and the renderer leaves it transparent.
void refuseInfinities(const std::vector<float>& values, const glm::ivec3& dims, const std::filesystem::path& file,
                      std::size_t step);

}  // namespace tstyles
