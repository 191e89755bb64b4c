// The automatic ray step (automatic_step.h).
#include "tstyles/scene/automatic_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/quaternion.hpp>

namespace tstyles {
namespace {

double lowerQuartileGap(const RectilinearGrid& grid, int axis) {
    if (!grid.isUneven(axis)) return grid.spacing[axis];
    const std::vector<double>& nodes = grid.axisPositions[std::size_t(axis)];
    std::vector<double> gaps;
    for (std::size_t node = 1; node < nodes.size(); ++node) gaps.push_back(nodes[node] - nodes[node - 1]);
    const auto quartile = gaps.begin() + std::ptrdiff_t(gaps.size() / 4);
    std::nth_element(gaps.begin(), quartile, gaps.end());
    return *quartile;
}

}  // namespace

std::optional<double> automaticStep(const Series& series, const DisplayFrame& frame, RayMode mode) {
    const double cells = rayModeInfo(mode).automaticStepInCells;
    double step = std::numeric_limits<double>::infinity();
    for (const TimeStep& timeStep : series.steps) {
        if (timeStep.isBeam()) {
            // One range cell, as short as the display draws any axis.
            const double leastDrawn = std::min({frame.scale.x, frame.scale.y, frame.scale.z});
            step = std::min(step, timeStep.beam().rangeSpacing() * leastDrawn);
            continue;
        }
        if (!std::holds_alternative<RectilinearGrid>(timeStep.grid)) return std::nullopt;
        const RectilinearGrid& grid = timeStep.rectilinear();
        const glm::dmat3 toWorld = glm::mat3_cast(timeStep.placement.rotation);
        for (int axis = 0; axis < 3; ++axis) {
            if (grid.dims[axis] < 2) continue;
            // A unit along the grid axis, as long as the display draws it.
            const double drawn = glm::length(frame.scale * (frame.rotation * toWorld[axis]));
            step = std::min(step, cells * lowerQuartileGap(grid, axis) * drawn);
        }
    }
    if (!std::isfinite(step) || !(step > 0.0)) return std::nullopt;
    return step;
}

}  // namespace tstyles
