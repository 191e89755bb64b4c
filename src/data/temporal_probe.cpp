// Probing a series at a place (temporal_probe.h).
#include "tstyles/data/temporal_probe.h"

#include <cmath>

#include "tstyles/core/errors.h"
#include "tstyles/data/beam_geometry.h"

namespace tstyles {

TemporalProbe::TemporalProbe(const Series& series) : series_(series), profiler_(series) {}

std::vector<std::optional<double>> TemporalProbe::valuesAt(const glm::dvec3& world) const {
    const double low = series_.valueRange[0];
    const double span = series_.valueRange[1] - series_.valueRange[0];
    std::vector<std::optional<double>> values;
    for (const std::optional<double>& density : profiler_.profile(world)) {
        if (!density || std::isnan(*density)) values.emplace_back();
        else values.emplace_back(low + *density * span);
    }
    return values;
}

glm::dvec3 nodePosition(const TimeStep& step, const glm::ivec3& node, const std::string& option) {
    const glm::ivec3 dims = step.dims();
    for (int axis = 0; axis < 3; ++axis)
        if (node[axis] < 0 || node[axis] >= dims[axis])
            throwInputError("", option,
                            "node (" + std::to_string(node.x) + ", " + std::to_string(node.y) + ", " +
                                std::to_string(node.z) + ") is outside the first time-step's grid of " +
                                std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " +
                                std::to_string(dims.z) + " nodes (each index from 0)");
    glm::dvec3 local{0.0};
    if (const StructuredGrid* structured = step.structured()) {
        local = structured->node(node.x, node.y, node.z);
    } else if (step.isBeam()) {
        local = beamSamplePosition(step.beam(), node.x, node.y, node.z);
    } else {
        const RectilinearGrid& grid = step.rectilinear();
        for (int axis = 0; axis < 3; ++axis)
            local[axis] = grid.isUneven(axis) ? grid.axisPositions[std::size_t(axis)][std::size_t(node[axis])]
                                              : double(node[axis]) * grid.spacing[axis];
    }
    return glm::dvec3(step.placement.gridToWorld() * glm::dvec4(local, 1.0));
}

std::vector<glm::dvec3> pointsAlong(const glm::dvec3& from, const glm::dvec3& to, std::size_t count) {
    std::vector<glm::dvec3> points;
    for (std::size_t index = 0; index < count; ++index)
        points.push_back(from + (to - from) * (double(index) / double(count - 1)));
    return points;
}

}  // namespace tstyles
