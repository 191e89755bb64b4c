// Which nodes of a beam grid a box needs, and the beam grid of just those (beam_grid_block.h).
#include "tstyles/data/beam_grid_block.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "tstyles/data/beam_geometry.h"

namespace tstyles {
namespace {

// The grid-local unit direction of every beam, azimuth fastest.
std::vector<glm::dvec3> beamDirections(const BeamGrid& grid) {
    std::vector<glm::dvec3> directions;
    directions.reserve(std::size_t(grid.dims.x) * std::size_t(grid.dims.y));
    for (int j = 0; j < grid.dims.y; ++j)
        for (int i = 0; i < grid.dims.x; ++i)
            directions.push_back(beamDirection(glm::radians(grid.azimuthDeg[std::size_t(i)]),
                                               glm::radians(grid.elevationDeg[std::size_t(j)])));
    return directions;
}

double rangeOf(const BeamGrid& grid, int bin) {
    if (bin == grid.dims.z - 1) return grid.maxRange;
    return grid.minRange + double(bin) * grid.rangeSpacing();
}

bool overlaps(const glm::dvec3& lower, const glm::dvec3& upper, const Bounds& box) {
    return glm::all(glm::lessThanEqual(lower, box.upper)) && glm::all(glm::greaterThanEqual(upper, box.lower));
}

// Cells along an axis of `count` nodes: one less, or the one node of an axis that has only one.
int cellsAlong(int count) { return std::max(count - 1, 1); }

}  // namespace

NodeBlock beamNodesMeeting(const BeamGrid& grid, const Bounds& local, int ghostNodes) {
    const glm::ivec3 dims = grid.dims;
    const std::vector<glm::dvec3> directions = beamDirections(grid);
    const auto direction = [&](int i, int j) { return directions[std::size_t(j) * std::size_t(dims.x) + std::size_t(i)]; };
    glm::ivec3 first(std::numeric_limits<int>::max());
    glm::ivec3 last(std::numeric_limits<int>::min());
    for (int j = 0; j < cellsAlong(dims.y); ++j)
        for (int i = 0; i < cellsAlong(dims.x); ++i) {
            const int i1 = std::min(i + 1, dims.x - 1);
            const int j1 = std::min(j + 1, dims.y - 1);
            const glm::dvec3 corners[4] = {direction(i, j), direction(i1, j), direction(i, j1), direction(i1, j1)};
            glm::dvec3 low = corners[0];
            glm::dvec3 high = corners[0];
            for (const glm::dvec3& corner : corners) {
                low = glm::min(low, corner);
                high = glm::max(high, corner);
            }
            // Directions between the corners lie on the unit sphere, beyond the corners' hull by at
            // most the sagitta of the cell's widest angle (a diagonal).
            const double widest = std::max(std::acos(std::clamp(glm::dot(corners[0], corners[3]), -1.0, 1.0)),
                                           std::acos(std::clamp(glm::dot(corners[1], corners[2]), -1.0, 1.0)));
            const double bulge = 1.0 - std::cos(0.5 * widest);
            for (int k = 0; k < cellsAlong(dims.z); ++k) {
                const double near = rangeOf(grid, k);
                const double far = rangeOf(grid, std::min(k + 1, dims.z - 1));
                const glm::dvec3 margin(far * bulge);
                const glm::dvec3 lower = glm::min(near * low, far * low) - margin;
                const glm::dvec3 upper = glm::max(near * high, far * high) + margin;
                if (!overlaps(lower, upper, local)) continue;
                first = glm::min(first, glm::ivec3(i, j, k));
                last = glm::max(last, glm::ivec3(i1, j1, std::min(k + 1, dims.z - 1)));
            }
        }
    if (first.x > last.x) {  // no cell meets the box
        first = glm::ivec3(0);
        last = glm::min(glm::ivec3(1), dims - 1);
    }
    first = glm::max(first - ghostNodes, glm::ivec3(0));
    last = glm::min(last + ghostNodes, dims - 1);
    return NodeBlock{first, last - first + 1};
}

BeamGrid cutBeamGrid(const BeamGrid& grid, const NodeBlock& nodes) {
    BeamGrid cut;
    cut.dims = nodes.count;
    const auto anglesOf = [](const std::vector<double>& angles, int first, int count) {
        return std::vector<double>(angles.begin() + first, angles.begin() + first + count);
    };
    cut.azimuthDeg = anglesOf(grid.azimuthDeg, nodes.first.x, nodes.count.x);
    cut.elevationDeg = anglesOf(grid.elevationDeg, nodes.first.y, nodes.count.y);
    cut.minRange = rangeOf(grid, nodes.first.z);
    cut.maxRange = rangeOf(grid, nodes.first.z + nodes.count.z - 1);
    return cut;
}

}  // namespace tstyles
