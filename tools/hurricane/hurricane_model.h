// An analytic hurricane, loosely after Hurricane Isabel (2003): a vortex with a clear eye, an eye
// wall that leans outward with height and spiral rain bands, whose centre moves west-northwest and
// then curves north towards a coastline. Cloud water in [0, 1]; no randomness, so every build
// writes the same bytes. Coordinates: x east, y north (both [0, 2]), h height ([0, kTopHeight]).
#pragma once

#include <glm/glm.hpp>

namespace hurricane {

inline constexpr double kDomainSize = 2.0;
inline constexpr double kTopHeight = 0.4;
inline constexpr double kDurationHours = 48.0;

// The storm's centre at `hours` after the start: a curved track (quadratic Bezier) heading
// west-northwest, then north-northwest, slowing as it turns.
glm::dvec2 stormCentre(double hours);

// Strength in [0, 1]: strongest in the middle of the period, weakening as it nears land.
double stormStrength(double hours);

// Land: west of a wavy coastline at x = coastline(y). The terrain height there (0 over the sea) rises inland.
double coastline(double north);
bool isLand(glm::dvec2 position);
double terrainHeight(glm::dvec2 position);

// Cloud water at (x, y, h) at `hours`.
double cloudWater(glm::dvec3 position, double hours);

}  // namespace hurricane
