// The coast of a map (coastline.h).
#include "coastline.h"

#include <cmath>
#include <cstdlib>

#include "box_projection.h"

namespace tstyles {
namespace {

// The grid-local position of a fractional node index along an axis (uneven axes interpolated,
// indices beyond the ends clamped to them).
double positionAlong(const RectilinearGrid& grid, int axis, double index) {
    const double last = double(grid.dims[axis] - 1);
    index = std::clamp(index, 0.0, last);
    if (!grid.isUneven(axis)) return index * grid.spacing[axis];
    const auto& positions = grid.axisPositions[std::size_t(axis)];
    const auto below = std::size_t(std::floor(index));
    if (below + 1 >= positions.size()) return positions.back();
    const double fraction = index - double(below);
    return positions[below] + fraction * (positions[below + 1] - positions[below]);
}

}  // namespace

std::vector<WorldSegment> coastSegments(const Series& display) {
    std::vector<WorldSegment> segments;
    if (display.steps.empty()) return segments;
    const TimeStep& step = display.steps.front();
    const auto* grid = std::get_if<RectilinearGrid>(&step.grid);
    if (grid == nullptr || step.density.size() != grid->voxelCount()) return segments;
    const glm::dmat4 toWorld = step.placement.gridToWorld();
    // The grid axis that runs up the display, and which end of it is the surface.
    int up = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (std::abs(toWorld[axis].y) > std::abs(toWorld[up].y)) up = axis;
    const int surface = toWorld[up].y > 0.0 ? grid->dims[up] - 1 : 0;
    const int a = (up + 1) % 3, b = (up + 2) % 3;
    const auto missingAt = [&](int i, int j) {
        glm::ivec3 node(0);
        node[up] = surface, node[a] = i, node[b] = j;
        const std::size_t index =
            (std::size_t(node.z) * std::size_t(grid->dims.y) + std::size_t(node.y)) * std::size_t(grid->dims.x) +
            std::size_t(node.x);
        return isMissing(step.density[index]);
    };
    const auto world = [&](double i, double j) {
        glm::dvec3 local(0.0);
        local[up] = positionAlong(*grid, up, surface);
        local[a] = positionAlong(*grid, a, i);
        local[b] = positionAlong(*grid, b, j);
        return glm::dvec3(toWorld * glm::dvec4(local, 1.0));
    };
    for (int i = 0; i < grid->dims[a]; ++i)
        for (int j = 0; j < grid->dims[b]; ++j) {
            const bool here = missingAt(i, j);
            if (i + 1 < grid->dims[a] && missingAt(i + 1, j) != here)
                segments.push_back({world(i + 0.5, j - 0.5), world(i + 0.5, j + 0.5)});
            if (j + 1 < grid->dims[b] && missingAt(i, j + 1) != here)
                segments.push_back({world(i - 0.5, j + 0.5), world(i + 0.5, j + 0.5)});
        }
    return segments;
}

void drawCoast(Canvas& canvas, const std::vector<WorldSegment>& segments, const View& view, const glm::vec4& ink) {
    const glm::ivec2 size(canvas.width(), canvas.height());
    for (const auto& [from, to] : segments) {
        const auto start = projectToImage(view, size, from);
        const auto end = projectToImage(view, size, to);
        if (start && end) canvas.drawLine(*start, *end, 1.5, ink);
    }
}

}  // namespace tstyles
