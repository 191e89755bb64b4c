// Writing a single-block Plot3D grid and solution file (little-endian, float32, Fortran records),
// the most common flavour, so the warped box can be read back through the Plot3D reader.
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "tstyles/data/structured_grid.h"

namespace warped_box {

void writePlot3DGrid(const tstyles::StructuredGrid& grid, const std::filesystem::path& file);
// q per node: density, momentum x, y, z, energy (each array nodes long, x fastest).
void writePlot3DSolution(glm::ivec3 dims, double time, const std::array<std::vector<float>, 5>& q,
                         const std::filesystem::path& file);

}  // namespace warped_box
