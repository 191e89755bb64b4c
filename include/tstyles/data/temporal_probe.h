// What a place held over time: every time-step sampled in its own grid at a world position
// (density_sampling.h: trilinear on rectilinear and uneven grids, point location in a structured
// grid's cells, the beam mapping of a sonar fan), the density mapping undone into the data's own
// values. For `tstyles probe` and Python's Series.at (docs/probe.md). GL-free.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/density_sampling.h"
#include "tstyles/data/series.h"

namespace tstyles {

class TemporalProbe {
public:
    explicit TemporalProbe(const Series& series);  // keeps a reference: `series` must outlive it

    // The value of every time-step at `world`, in the data's own unit; none where the time-step's
    // grid does not reach the place or has no data there. Values outside the series' value range
    // (--range) come back clamped to it, as the densities are.
    std::vector<std::optional<double>> valuesAt(const glm::dvec3& world) const;

private:
    const Series& series_;
    TemporalProfiler profiler_;
};

// The world position of node (i, j, k) of `step`'s grid; `option` names the place in a message
// when the node lies outside the grid (an InputError listing its size).
glm::dvec3 nodePosition(const TimeStep& step, const glm::ivec3& node, const std::string& option);

// `count` evenly spaced positions from `from` to `to`, both included (count >= 2).
std::vector<glm::dvec3> pointsAlong(const glm::dvec3& from, const glm::dvec3& to, std::size_t count);

}  // namespace tstyles
