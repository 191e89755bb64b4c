// The seabed under the survey: an undulating floor about 88 m down, and the echo it returns: a
// strong peak at the floor and a weaker tail from the sediment just below it. A beam that meets the
// floor obliquely lights a footprint that spans a stretch of ranges, so the peak widens with the
// beam's width, its range and its angle from the vertical.
#pragma once

#include <glm/glm.hpp>

namespace sonar {

// Depth of the floor (metres, positive down) under the world point (x, z).
double seabedDepth(double x, double z);

// Linear backscattered intensity (before range attenuation and speckle) at a world point that a
// beam of angular width `beamWidthRad` reaches at `range` along the world direction `beam`.
double seabedEcho(const glm::dvec3& world, const glm::dvec3& beam, double range, double beamWidthRad);

}  // namespace sonar
