// The inverse map of a structured grid: a regular lattice over the grid's local bounding box whose
// texels hold the computational coordinates (i, j, k) of their position and whether it lies inside
// the grid. Filled on the CPU by exact point location; the renderer uploads it as a 3D texture and
// reads it with trilinear filtering (`lookup` does the same on the CPU, for tests).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/structured_grid.h"

namespace tstyles {

struct InverseMap {
    glm::ivec3 dims{0};
    glm::ivec3 gridDims{0};  // the structured grid's node counts: computational coordinates lie in [0, gridDims - 1]
    // Texel m sits at lower + m * (upper - lower) / (dims - 1): the texels span the grid's bounds.
    glm::dvec3 lower{0.0};
    glm::dvec3 upper{0.0};
    // rgb: computational coordinates; a: 1 inside the grid, 0 outside. Texels just outside hold
    // the extrapolation of the nearest cell (coordinates a little below 0 or above dims - 1), so
    // that filtering between them and texels inside stays accurate up to the boundary; lookups
    // clamp to the grid after filtering.
    std::vector<glm::vec4> texels;

    std::size_t bytes() const { return texels.size() * sizeof(glm::vec4); }
    // Trilinear interpolation of the texels at a grid-local point (clamped to the bounds), its
    // coordinates clamped to the grid.
    glm::vec4 lookup(glm::dvec3 local) const;
};

// Texels per cell along each axis, capped so that one map stays below 256 texels per axis.
glm::ivec3 inverseMapDims(const StructuredGrid& grid, int texelsPerCell = 2);

InverseMap buildInverseMap(const StructuredGrid& grid, glm::ivec3 dims);

}  // namespace tstyles
