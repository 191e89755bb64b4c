// The fish school: a cloud of scatterers inside a drifting, breathing, bending ellipsoid. Each fish
// keeps a place in the school's normalised frame (drawn so that the number of fish per volume falls
// as (1 - r^2)^1.5 toward the edge) and wanders a little from ping to ping; the envelope's centre,
// axes, heading and bend change with time.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace sonar {

// The school's envelope at one moment, in world coordinates (y up, metres).
struct SchoolShape {
    glm::dvec3 centre{0.0};
    glm::dvec3 semiAxes{1.0};  // along x (length), y (height), z (width) of the school's own frame
    double headingRad = 0.0;   // turn of the school's frame about world y
    double bend = 0.0;         // normalised y offset added as bend * (x^2 - 1/3)
    // The school packs and loosens its core: a fish at normalised radius r swims at r^packing,
    // so above 1 the core is denser (the edge stays where it is).
    double packing = 1.0;

    // The point's position in the unit-ball frame of the school (inverse of toWorld).
    glm::dvec3 toNormalised(const glm::dvec3& world) const;
    glm::dvec3 toWorld(const glm::dvec3& normalised) const;
    // The envelope's radius at the point: below 1 inside the school, 1 on its edge.
    double normalisedRadius(const glm::dvec3& world) const { return glm::length(toNormalised(world)); }
};

// The envelope at time t (seconds).
SchoolShape schoolShapeAt(double time);

struct Fish {
    glm::dvec3 home{0.0};  // normalised position in the unit ball
    double strength = 1.0; // linear backscattering strength relative to the mean fish (mean 1)
};

// `count` fish drawn from `seed`; the same for every ping.
std::vector<Fish> drawSchool(int count, std::uint32_t seed);

// Where each fish is at ping time t: its home packed by the envelope's `packing`, wandered by a
// per-ping offset (from `pingSeed`), mapped through the envelope at t. World coordinates.
std::vector<glm::dvec3> fishPositions(const std::vector<Fish>& fish, const SchoolShape& shape,
                                      std::uint32_t pingSeed);

}  // namespace sonar
