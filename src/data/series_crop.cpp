// Cutting a series to the block of one process (series_crop.h).
#include "tstyles/data/series_crop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tstyles {
namespace {

// The first and last node index [first, last] along one axis whose cells cover grid-local
// [lower, upper], widened by `ghost` nodes and clamped; at least two nodes.
glm::ivec2 nodeRange(const RectilinearGrid& grid, int axis, double lower, double upper, int ghost) {
    const int count = grid.dims[axis];
    int first = 0;
    int last = count - 1;
    if (grid.isUneven(axis)) {
        const std::vector<double>& nodes = grid.axisPositions[std::size_t(axis)];
        // The last node at or below `lower`, the first at or above `upper`.
        first = int(std::upper_bound(nodes.begin(), nodes.end(), lower) - nodes.begin()) - 1;
        last = int(std::lower_bound(nodes.begin(), nodes.end(), upper) - nodes.begin());
    } else {
        const double spacing = grid.spacing[axis];
        const double from = std::floor(lower / spacing);
        const double to = std::ceil(upper / spacing);
        first = int(std::clamp(from, -1.0, double(count)));
        last = int(std::clamp(to, -1.0, double(count)));
    }
    first = std::clamp(first - ghost, 0, count - 1);
    last = std::clamp(last + ghost, 0, count - 1);
    if (last - first < 1) {  // the box misses this axis' extent: keep the nearest edge cell
        first = std::min(first, count - 2);
        last = first + 1;
    }
    return {first, last};
}

// The grid-local box that the world box covers (its corners taken to the grid's frame).
Bounds localBounds(const Placement& placement, const Bounds& box) {
    const glm::dmat4 toLocal = glm::inverse(placement.gridToWorld());
    Bounds local{glm::dvec3(std::numeric_limits<double>::infinity()),
                 glm::dvec3(-std::numeric_limits<double>::infinity())};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 world((corner & 1) ? box.upper.x : box.lower.x, (corner & 2) ? box.upper.y : box.lower.y,
                               (corner & 4) ? box.upper.z : box.lower.z);
        const glm::dvec3 point(toLocal * glm::dvec4(world, 1.0));
        local.lower = glm::min(local.lower, point);
        local.upper = glm::max(local.upper, point);
    }
    return local;
}

template <typename Value>
std::vector<Value> cropValues(const std::vector<Value>& values, glm::ivec3 dims, glm::ivec3 first, glm::ivec3 count) {
    std::vector<Value> cropped;
    cropped.reserve(std::size_t(count.x) * std::size_t(count.y) * std::size_t(count.z));
    for (int z = first.z; z < first.z + count.z; ++z)
        for (int y = first.y; y < first.y + count.y; ++y) {
            const std::size_t row = (std::size_t(z) * std::size_t(dims.y) + std::size_t(y)) * std::size_t(dims.x);
            const auto begin = values.begin() + std::ptrdiff_t(row + std::size_t(first.x));
            cropped.insert(cropped.end(), begin, begin + count.x);
        }
    return cropped;
}

// The nodes of `step` that the box needs: the first, how many, and the cut grid.
struct KeptNodes {
    glm::ivec3 first{0};
    glm::ivec3 count{0};
    glm::dvec3 offset{0.0};  // grid-local position of the first kept node
    RectilinearGrid grid;
};

KeptNodes keptNodes(const TimeStep& step, const Bounds& box, int ghost) {
    const RectilinearGrid& grid = step.rectilinear();
    const Bounds local = localBounds(step.placement, box);
    KeptNodes kept;
    kept.grid.spacing = grid.spacing;
    for (int axis = 0; axis < 3; ++axis) {
        const glm::ivec2 range = nodeRange(grid, axis, local.lower[axis], local.upper[axis], ghost);
        kept.first[axis] = range.x;
        kept.count[axis] = range.y - range.x + 1;
        if (grid.isUneven(axis)) {
            const std::vector<double>& nodes = grid.axisPositions[std::size_t(axis)];
            kept.offset[axis] = nodes[std::size_t(range.x)];
            std::vector<double>& positions = kept.grid.axisPositions[std::size_t(axis)];
            for (int node = range.x; node <= range.y; ++node)
                positions.push_back(nodes[std::size_t(node)] - kept.offset[axis]);
        } else {
            kept.offset[axis] = double(range.x) * grid.spacing[axis];
        }
    }
    kept.grid.dims = kept.count;
    return kept;
}

}  // namespace

std::size_t croppedVoxelCount(const TimeStep& step, const Bounds& box, int ghostNodes) {
    const std::optional<NodeBlock> kept = nodesKeptOf(step, box, ghostNodes);
    return kept ? kept->nodeCount() : gridVoxelCount(step.grid);
}

std::optional<NodeBlock> nodesKeptOf(const TimeStep& step, const Bounds& box, int ghostNodes) {
    if (!std::holds_alternative<RectilinearGrid>(step.grid)) return std::nullopt;  // kept whole
    const KeptNodes kept = keptNodes(step, box, ghostNodes);
    return NodeBlock{kept.first, kept.count};
}

namespace {

// Moves `step`'s grid and placement to the kept nodes; its values must be theirs already.
void cutGridTo(TimeStep& step, KeptNodes kept) {
    const std::size_t keptCount = kept.grid.voxelCount();
    if (step.density.size() != keptCount || (step.mask && step.mask->size() != keptCount))
        throw std::logic_error("cropTimeStepGridToBox: the time-step's values are not those of its block (" +
                               std::to_string(step.density.size()) + " values for " + std::to_string(keptCount) +
                               " kept nodes)");
    step.placement.origin = glm::dvec3(step.placement.gridToWorld() * glm::dvec4(kept.offset, 1.0));
    step.grid = std::move(kept.grid);
}

}  // namespace

void cropTimeStepGridToBox(TimeStep& step, const Bounds& box, int ghostNodes) {
    if (!std::holds_alternative<RectilinearGrid>(step.grid)) return;  // kept whole (series_crop.h)
    cutGridTo(step, keptNodes(step, box, ghostNodes));
}

void cropTimeStepToBox(TimeStep& step, const Bounds& box, int ghostNodes) {
    if (!std::holds_alternative<RectilinearGrid>(step.grid)) return;  // kept whole (series_crop.h)
    KeptNodes kept = keptNodes(step, box, ghostNodes);
    const glm::ivec3 dims = step.rectilinear().dims;
    step.density = cropValues(step.density, dims, kept.first, kept.count);
    if (step.mask) step.mask = cropValues(*step.mask, dims, kept.first, kept.count);
    cutGridTo(step, std::move(kept));
}

Series cropSeriesToBox(Series series, const Bounds& box, int ghostNodes) {
    for (std::size_t index = 0; index < series.steps.size(); ++index)
        cropTimeStepToBox(series.steps[index], box, ghostNodes);
    return series;
}

}  // namespace tstyles
