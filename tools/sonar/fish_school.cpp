// Fish school envelope and scatterers (see fish_school.h).
#include "fish_school.h"

#include <cmath>

#include "sonar_random.h"

namespace sonar {
namespace {

constexpr double kWanderNormalised = 0.04;  // a fish's per-ping wander, in school radii

}  // namespace

glm::dvec3 SchoolShape::toNormalised(const glm::dvec3& world) const {
    const glm::dvec3 offset = world - centre;
    // Undo the heading turn about y (a turn by h takes x to (cos h, 0, -sin h)).
    const double c = std::cos(headingRad);
    const double s = std::sin(headingRad);
    const glm::dvec3 local(c * offset.x - s * offset.z, offset.y, s * offset.x + c * offset.z);
    glm::dvec3 bent = local / semiAxes;
    bent.y -= bend * (bent.x * bent.x - 1.0 / 3.0);
    return bent;
}

glm::dvec3 SchoolShape::toWorld(const glm::dvec3& normalised) const {
    glm::dvec3 bent = normalised;
    bent.y += bend * (bent.x * bent.x - 1.0 / 3.0);
    const glm::dvec3 local = bent * semiAxes;
    const double c = std::cos(headingRad);
    const double s = std::sin(headingRad);
    return centre + glm::dvec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z);
}

SchoolShape schoolShapeAt(double time) {
    SchoolShape shape;
    // Drifts along the vessel's course more slowly than the vessel (2.25 m/s against 3 m/s), so it
    // slides backward through the fans, rising and sinking a little and drifting to starboard.
    shape.centre = glm::dvec3(6.0 + 2.25 * time, -45.0 + 4.0 * std::sin(time / 6.0), 4.0 + 0.3 * time);
    // Stretches and flattens as it swims; the volume changes by less than the axes do.
    shape.semiAxes = glm::dvec3(11.0 * (1.0 + 0.3 * std::sin(time / 5.0)),
                                5.0 * (1.0 + 0.25 * std::cos(time / 4.0)),
                                8.0 * (1.0 - 0.2 * std::sin(time / 5.0)));
    shape.headingRad = glm::radians(10.0 + 25.0 * std::sin(time / 10.0));
    shape.bend = 0.45 * std::sin(time / 7.0);
    shape.packing = 1.15 + 0.4 * std::sin(time / 2.5);  // between 0.75 and 1.55
    return shape;
}

std::vector<Fish> drawSchool(int count, std::uint32_t seed) {
    SonarRandom random(seed);
    std::vector<Fish> fish;
    fish.reserve(std::size_t(count));
    while (int(fish.size()) < count) {
        const glm::dvec3 candidate(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0),
                                   random.uniform(-1.0, 1.0));
        const double r2 = glm::dot(candidate, candidate);
        const double keep = random.uniform();
        if (r2 >= 1.0 || keep >= std::pow(1.0 - r2, 1.5)) continue;
        // Log-normal target strengths with mean 1 (sigma 0.5 in natural-log units).
        const double strength = std::exp(0.5 * random.normal() - 0.125);
        fish.push_back({candidate, strength});
    }
    return fish;
}

std::vector<glm::dvec3> fishPositions(const std::vector<Fish>& fish, const SchoolShape& shape,
                                      std::uint32_t seed) {
    SonarRandom random(seed);
    std::vector<glm::dvec3> positions;
    positions.reserve(fish.size());
    for (const Fish& one : fish) {
        const glm::dvec3 wander(random.normal(), random.normal(), random.normal());
        const double radius = glm::length(one.home);
        const glm::dvec3 packed = radius > 0.0 ? one.home * std::pow(radius, shape.packing - 1.0) : one.home;
        positions.push_back(shape.toWorld(packed + kWanderNormalised * wander));
    }
    return positions;
}

}  // namespace sonar
