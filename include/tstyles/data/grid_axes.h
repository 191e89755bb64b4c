// Node positions along the axes of a rectilinear grid, even or uneven (RectilinearGrid::axisPositions):
// the one place that turns node indices into grid-local positions and back. GL-free.
#pragma once

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

// Grid-local position of node `index` along `axis` (a fractional index interpolates linearly).
double nodePosition(const RectilinearGrid& grid, int axis, double index);

// The fractional node index of grid-local position `local` along `axis`: the inverse of
// nodePosition, piecewise linear between nodes. Positions outside the grid extrapolate linearly
// from the first or last cell, so callers can tell "outside" from the result.
double fractionalIndex(const RectilinearGrid& grid, int axis, double local);

// The smallest distance between neighbouring nodes along any axis.
double finestSpacing(const RectilinearGrid& grid);

// Grid-local position of a fractional voxel coordinate, and its inverse.
glm::dvec3 voxelToLocal(const RectilinearGrid& grid, const glm::dvec3& voxel);
glm::dvec3 localToVoxel(const RectilinearGrid& grid, const glm::dvec3& local);

}  // namespace tstyles
