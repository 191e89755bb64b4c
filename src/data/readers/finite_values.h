// NaN or Inf that a file does not declare as missing is bad input: one check, one message shape.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles {

// Throws an InputError naming the file, the time-step and the first non-finite voxel's (x, y, z);
// `remedy` says how the format could have declared it missing (or that it cannot).
void requireFiniteValues(const std::vector<float>& values, const glm::ivec3& dims, const std::filesystem::path& file,
                         std::size_t step, const std::string& remedy);

}  // namespace tstyles
