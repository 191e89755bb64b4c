// Reading a time-step's density at a world position on the CPU, the way the raycaster reads its
// volume texture: trilinear between the grid's samples. For picking and probes, not for rendering.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

// The time-step's density at `world`, or none when the position lies outside its grid (a
// tolerance of a thousandth of a voxel lets points on the boundary count as inside). Inside the
// grid but where it has no data (missing values, as the renderer decides: the corners with data
// weigh less than half) the result is missingDensity(); test it with isMissing.
std::optional<double> sampleDensity(const TimeStep& step, const glm::dvec3& world);

// The density of every time-step at `world`: the temporal profile of that point.
std::vector<std::optional<double>> temporalProfile(const Series& series, const glm::dvec3& world);

}  // namespace tstyles
