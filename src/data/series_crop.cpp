// Cutting a series to the block of one process (series_crop.h).
#include "tstyles/data/series_crop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "tstyles/data/beam_grid_block.h"

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

// The nodes of `step` that the box needs: the first, how many, and the cut grid and its placement.
struct KeptNodes {
    glm::ivec3 first{0};
    glm::ivec3 count{0};
    Grid grid;
    Placement placement;
};

KeptNodes keptRectilinearNodes(const TimeStep& step, const RectilinearGrid& grid, const Bounds& local, int ghost) {
    KeptNodes kept;
    RectilinearGrid cut;
    cut.spacing = grid.spacing;
    glm::dvec3 offset(0.0);  // grid-local position of the first kept node
    for (int axis = 0; axis < 3; ++axis) {
        const glm::ivec2 range = nodeRange(grid, axis, local.lower[axis], local.upper[axis], ghost);
        kept.first[axis] = range.x;
        kept.count[axis] = range.y - range.x + 1;
        if (grid.isUneven(axis)) {
            const std::vector<double>& nodes = grid.axisPositions[std::size_t(axis)];
            offset[axis] = nodes[std::size_t(range.x)];
            std::vector<double>& positions = cut.axisPositions[std::size_t(axis)];
            for (int node = range.x; node <= range.y; ++node) positions.push_back(nodes[std::size_t(node)] - offset[axis]);
        } else {
            offset[axis] = double(range.x) * grid.spacing[axis];
        }
    }
    cut.dims = kept.count;
    kept.grid = std::move(cut);
    kept.placement = step.placement;
    kept.placement.origin = glm::dvec3(step.placement.gridToWorld() * glm::dvec4(offset, 1.0));
    return kept;
}

// Rectilinear and beam time-steps are cut; none for a structured one (kept whole, series_crop.h).
std::optional<KeptNodes> keptNodes(const TimeStep& step, const Bounds& box, int ghost) {
    const Bounds local = localBounds(step.placement, box);
    if (const auto* grid = std::get_if<RectilinearGrid>(&step.grid)) return keptRectilinearNodes(step, *grid, local, ghost);
    if (const auto* grid = std::get_if<BeamGrid>(&step.grid)) {
        const NodeBlock nodes = beamNodesMeeting(*grid, local, ghost);
        return KeptNodes{nodes.first, nodes.count, cutBeamGrid(*grid, nodes), step.placement};
    }
    return std::nullopt;
}

}  // namespace

std::size_t croppedVoxelCount(const TimeStep& step, const Bounds& box, int ghostNodes) {
    const std::optional<NodeBlock> kept = nodesKeptOf(step, box, ghostNodes);
    return kept ? kept->nodeCount() : gridVoxelCount(step.grid);
}

std::optional<NodeBlock> nodesKeptOf(const TimeStep& step, const Bounds& box, int ghostNodes) {
    const std::optional<KeptNodes> kept = keptNodes(step, box, ghostNodes);
    if (!kept) return std::nullopt;
    return NodeBlock{kept->first, kept->count};
}

namespace {

// Moves `step`'s grid and placement to the kept nodes; its values must be theirs already.
void cutGridTo(TimeStep& step, KeptNodes kept) {
    const std::size_t keptCount = NodeBlock{kept.first, kept.count}.nodeCount();
    if (step.density.size() != keptCount || (step.mask && step.mask->size() != keptCount))
        throw std::logic_error("cropTimeStepGridToBox: the time-step's values are not those of its block (" +
                               std::to_string(step.density.size()) + " values for " + std::to_string(keptCount) +
                               " kept nodes)");
    step.placement = kept.placement;
    step.grid = std::move(kept.grid);
}

}  // namespace

void cropTimeStepGridToBox(TimeStep& step, const Bounds& box, int ghostNodes) {
    if (std::optional<KeptNodes> kept = keptNodes(step, box, ghostNodes)) cutGridTo(step, std::move(*kept));
}

void cropTimeStepToBox(TimeStep& step, const Bounds& box, int ghostNodes) {
    std::optional<KeptNodes> kept = keptNodes(step, box, ghostNodes);
    if (!kept) return;  // kept whole (series_crop.h)
    const glm::ivec3 dims = gridDims(step.grid);
    step.density = cropValues(step.density, dims, kept->first, kept->count);
    if (step.mask) step.mask = cropValues(*step.mask, dims, kept->first, kept->count);
    cutGridTo(step, std::move(*kept));
}

Series cropSeriesToBox(Series series, const Bounds& box, int ghostNodes) {
    for (std::size_t index = 0; index < series.steps.size(); ++index)
        cropTimeStepToBox(series.steps[index], box, ghostNodes);
    return series;
}

}  // namespace tstyles
