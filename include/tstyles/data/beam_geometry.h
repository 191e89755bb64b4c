// Geometry of beam (sonar) grids: from a grid-local position to fractional sample coordinates and
// back, the fan's boundary as triangles (the proxy geometry of the entry/exit buffers), and the
// sizes the renderer needs. GL-free; shaders/beam_grid.glsl does the same mapping on the GPU.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

// The unit direction of a beam at the given azimuth and elevation (radians).
glm::dvec3 beamDirection(double azimuthRad, double elevationRad);

// The fractional beam index of `angleDeg` in a strictly increasing list of beam angles: 0 at the
// first, 1 at the second, linear in between. None outside [first, last].
std::optional<double> fractionalBeamIndex(const std::vector<double>& anglesDeg, double angleDeg);

// Fractional sample coordinates (i, j, k) of a grid-local position; none outside the fan.
std::optional<glm::dvec3> beamVoxel(const BeamGrid& grid, const glm::dvec3& local);

// The grid-local position of sample (i, j, k).
glm::dvec3 beamSamplePosition(const BeamGrid& grid, int i, int j, int k);

// `count` angles evenly spread from `first` to `last`.
std::vector<double> evenBeamAngles(double firstDeg, double lastDeg, int count);

// Whether the angles are evenly spread (to 1e-9 degrees), so the manifest can state the extent only.
bool areEvenBeamAngles(const std::vector<double>& anglesDeg);

// A closed triangle mesh, in grid-local coordinates, that encloses the fan: its four planar sides,
// the near cap (at minRange, left out when that is 0) and the far cap, tessellated and pushed out
// just far enough that its flat facets lie outside the sphere of radius maxRange. Each triangle is
// wound counter-clockwise seen from outside.
using Triangle = std::array<glm::dvec3, 3>;
std::vector<Triangle> beamFanBoundary(const BeamGrid& grid, int subdivisions = 16);

// The smallest distance between neighbouring samples: the range spacing, or the arc between
// neighbouring beams at the maximum range when that is shorter.
double beamFinestSpacing(const BeamGrid& grid);

}  // namespace tstyles
