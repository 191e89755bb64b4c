// Bounds of what the STF leaves visible (visible_bounds.h).
#include "tstyles/scene/visible_bounds.h"

#include <algorithm>
#include <array>
#include <limits>

#include "tstyles/data/grid_axes.h"

namespace tstyles {
namespace {

constexpr int kOpacityTableSize = 1024;

// The STF's opacity at each of kOpacityTableSize densities, as the renderer's lookup table has it.
std::array<bool, kOpacityTableSize> visibleDensities(const Stf& stf) {
    std::array<bool, kOpacityTableSize> visible{};
    for (int i = 0; i < kOpacityTableSize; ++i)
        visible[std::size_t(i)] = stf.curve.evaluate(double(i) / (kOpacityTableSize - 1)).opacity > 0.0;
    return visible;
}

NodeIndexBox visibleNodes(const TimeStep& step, const std::array<bool, kOpacityTableSize>& visible) {
    NodeIndexBox box;
    if (step.density.size() != gridVoxelCount(step.grid)) return box;  // an outline's time-step
    const glm::ivec3 dims = step.dims();
    std::size_t index = 0;
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x, ++index) {
                const float density = step.density[index];
                if (isMissing(density)) continue;
                const int entry = int(std::clamp(density, 0.0f, 1.0f) * (kOpacityTableSize - 1) + 0.5f);
                if (!visible[std::size_t(entry)]) continue;
                box.lower = glm::min(box.lower, glm::ivec3(x, y, z));
                box.upper = glm::max(box.upper, glm::ivec3(x, y, z));
            }
    return box;
}

void include(Bounds& bounds, const Bounds& more) {
    bounds.lower = glm::min(bounds.lower, more.lower);
    bounds.upper = glm::max(bounds.upper, more.upper);
}

// The world box of a rectilinear time-step's voxels lower..upper (their nodes' positions).
Bounds worldBoxOf(const TimeStep& step, const NodeIndexBox& box) {
    const RectilinearGrid& grid = step.rectilinear();
    const glm::dmat4 toWorld = step.placement.gridToWorld();
    Bounds bounds{glm::dvec3(std::numeric_limits<double>::infinity()),
                  glm::dvec3(-std::numeric_limits<double>::infinity())};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 voxel{(corner & 1) ? box.upper.x : box.lower.x, (corner & 2) ? box.upper.y : box.lower.y,
                               (corner & 4) ? box.upper.z : box.lower.z};
        const glm::dvec3 world(toWorld * glm::dvec4(voxelToLocal(grid, voxel), 1.0));
        bounds.lower = glm::min(bounds.lower, world);
        bounds.upper = glm::max(bounds.upper, world);
    }
    return bounds;
}

}  // namespace

std::vector<NodeIndexBox> visibleNodeBoxes(const Series& series, const Stf& stf) {
    const auto visible = visibleDensities(stf);
    std::vector<NodeIndexBox> boxes;
    boxes.reserve(series.steps.size());
    for (const TimeStep& step : series.steps) boxes.push_back(visibleNodes(step, visible));
    return boxes;
}

Bounds boundsOfVisibleNodes(const Series& series, const std::vector<NodeIndexBox>& boxes) {
    Bounds bounds{glm::dvec3(std::numeric_limits<double>::infinity()),
                  glm::dvec3(-std::numeric_limits<double>::infinity())};
    bool any = false;
    for (std::size_t index = 0; index < series.steps.size(); ++index) {
        const TimeStep& step = series.steps[index];
        const NodeIndexBox& box = boxes.at(index);
        if (box.empty()) continue;
        any = true;
        include(bounds, std::holds_alternative<RectilinearGrid>(step.grid) ? worldBoxOf(step, box)
                                                                            : series.worldBounds(index));
    }
    return any ? bounds : series.worldBounds();
}

Bounds visibleBounds(const Series& series, const Stf& stf) {
    return boundsOfVisibleNodes(series, visibleNodeBoxes(series, stf));
}

}  // namespace tstyles
