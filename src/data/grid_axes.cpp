// Even axes are an affine map between index and position; uneven ones a piecewise linear one
// through their node list.
#include "tstyles/data/grid_axes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tstyles {

double nodePosition(const RectilinearGrid& grid, int axis, double index) {
    if (!grid.isUneven(axis)) return index * grid.spacing[axis];
    const std::vector<double>& nodes = grid.axisPositions[std::size_t(axis)];
    const int last = int(nodes.size()) - 1;
    const int cell = std::clamp(int(std::floor(index)), 0, last - 1);
    const double fraction = index - double(cell);
    return nodes[std::size_t(cell)] + fraction * (nodes[std::size_t(cell) + 1] - nodes[std::size_t(cell)]);
}

double fractionalIndex(const RectilinearGrid& grid, int axis, double local) {
    if (!grid.isUneven(axis)) return local / grid.spacing[axis];
    const std::vector<double>& nodes = grid.axisPositions[std::size_t(axis)];
    // The cell [nodes[cell], nodes[cell + 1]] holding `local`, or the first or last cell outside.
    const auto above = std::upper_bound(nodes.begin(), nodes.end(), local);
    const std::size_t cell =
        std::size_t(std::clamp<std::ptrdiff_t>((above - nodes.begin()) - 1, 0, std::ptrdiff_t(nodes.size()) - 2));
    return double(cell) + (local - nodes[cell]) / (nodes[cell + 1] - nodes[cell]);
}

double finestSpacing(const RectilinearGrid& grid) {
    double finest = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (!grid.isUneven(axis)) {
            finest = std::min(finest, grid.spacing[axis]);
            continue;
        }
        const std::vector<double>& nodes = grid.axisPositions[std::size_t(axis)];
        for (std::size_t node = 1; node < nodes.size(); ++node) finest = std::min(finest, nodes[node] - nodes[node - 1]);
    }
    return finest;
}

glm::dvec3 voxelToLocal(const RectilinearGrid& grid, const glm::dvec3& voxel) {
    return {nodePosition(grid, 0, voxel.x), nodePosition(grid, 1, voxel.y), nodePosition(grid, 2, voxel.z)};
}

glm::dvec3 localToVoxel(const RectilinearGrid& grid, const glm::dvec3& local) {
    return {fractionalIndex(grid, 0, local.x), fractionalIndex(grid, 1, local.y), fractionalIndex(grid, 2, local.z)};
}

}  // namespace tstyles
