// The super-ellipsoid's implicit function and density profile (see superellipsoid_shape.h).
#include "superellipsoid_shape.h"

#include <algorithm>
#include <cmath>

namespace superellipsoid {

namespace {

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace

double SuperEllipsoidShape::gauge(const glm::dvec3& local) const {
    const glm::dvec3 scaled = glm::abs(local / halfAxes);
    const double crossSection = std::pow(scaled.x, 2.0 / e2) + std::pow(scaled.y, 2.0 / e2);
    const double implicit = std::pow(crossSection, e2 / e1) + std::pow(scaled.z, 2.0 / e1);
    // The implicit function is homogeneous of degree 2/e1; this power makes it degree 1.
    return std::pow(implicit, e1 / 2.0);
}

double SuperEllipsoidShape::density(const glm::dvec3& local) const {
    // Cheap rejection: the gauge is at least each axis' scaled coordinate, so anything outside
    // the non-zero box is 0 without the powers.
    const glm::dvec3 scaled = glm::abs(local / halfAxes);
    if (std::max({scaled.x, scaled.y, scaled.z}) >= shellOuter) return 0.0;
    return 1.0 - smoothstep(shellInner, shellOuter, gauge(local));
}

double SuperEllipsoidShape::depthBelowCentre(double angle) const {
    // The cross-section |x/a|^p + |y/b|^p = 1 has the support function
    // h(d) = (|a dx|^q + |b dy|^q)^(1/q) with the dual exponent q = p / (p - 1). The world's
    // downward direction, seen from the turned object, is (-sin, -cos).
    const double p = 2.0 / e2;
    const double q = p / (p - 1.0);
    const double alongX = std::abs(halfAxes.x * std::sin(angle));
    const double alongY = std::abs(halfAxes.y * std::cos(angle));
    return std::pow(std::pow(alongX, q) + std::pow(alongY, q), 1.0 / q);
}

}  // namespace superellipsoid
