// The parts of the analytic hurricane: track, strength, coastline, and the cloud-water field as a
// sum of eye wall, rain bands and a thin outflow layer, shaped by a vertical profile.
#include "hurricane_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hurricane {
namespace {

constexpr double kPi = std::numbers::pi;

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Deterministic small-scale texture: a few incommensurate sines, in [-1, 1].
double ripple(glm::dvec3 p) {
    return (std::sin(23.0 * p.x + 7.0 * p.y + 31.0 * p.z) + std::sin(-11.0 * p.x + 29.0 * p.y + 3.0) +
            std::sin(17.0 * p.x - 13.0 * p.y + 41.0 * p.z + 1.0)) / 3.0;
}

}  // namespace

glm::dvec2 stormCentre(double hours) {
    // Ease-out in time: the storm slows down while it recurves, as Isabel did before landfall.
    const double s = 1.0 - (1.0 - hours / kDurationHours) * (1.0 - 0.35 * hours / kDurationHours);
    const glm::dvec2 start(1.6, 0.35);
    const glm::dvec2 bend(0.85, 0.55);
    const glm::dvec2 end(0.8, 1.45);
    return (1.0 - s) * (1.0 - s) * start + 2.0 * s * (1.0 - s) * bend + s * s * end;
}

double stormStrength(double hours) {
    const double growth = smoothstep(0.0, 18.0, hours);
    const double decay = 1.0 - 0.35 * smoothstep(30.0, kDurationHours, hours);
    return 0.7 + 0.3 * growth * decay - 0.1 * smoothstep(36.0, kDurationHours, hours);
}

double coastline(double north) {
    return 0.42 + 0.18 * north + 0.06 * std::sin(4.0 * north) + 0.03 * std::sin(11.0 * north);
}

bool isLand(glm::dvec2 position) { return position.x < coastline(position.y); }

double terrainHeight(glm::dvec2 position) {
    if (!isLand(position)) return 0.0;
    // A coastal plain rising to hills inland: up to about a sixth of the column.
    return 0.006 + 0.05 * smoothstep(0.0, 0.5, coastline(position.y) - position.x) +
           0.004 * (1.0 + std::sin(9.0 * position.x * position.y));
}

double cloudWater(glm::dvec3 position, double hours) {
    const glm::dvec2 centre = stormCentre(hours);
    const glm::dvec2 offset = glm::dvec2(position) - centre;
    const double r = glm::length(offset);
    const double theta = std::atan2(offset.y, offset.x);
    const double height = position.z / kTopHeight;  // 0 at the surface, 1 at the top
    const double strength = stormStrength(hours);

    // Eye wall: a ring leaning outward with height; the eye inside it is clear.
    const double wallRadius = 0.085 + 0.07 * height;
    const double wall = 0.9 * std::exp(-std::pow((r - wallRadius) / 0.025, 2.0)) * smoothstep(0.0, 0.06, height) *
                        (1.0 - smoothstep(0.75, 0.95, height));

    // Spiral rain bands: two logarithmic spirals turning counter-clockwise inward, rotating with time.
    const double spiralPhase = theta + 2.2 * std::log(std::max(r, 1e-3) / 0.12) - 0.35 * hours;
    const double band = std::pow(0.5 + 0.5 * std::cos(2.0 * spiralPhase), 12.0);
    const double bandReach = smoothstep(0.12, 0.2, r) * (1.0 - smoothstep(0.45, 0.8, r));
    const double bands = 0.75 * band * bandReach * smoothstep(0.0, 0.05, height) * (1.0 - smoothstep(0.35, 0.6, height));

    // Outflow: a thin, faint cirrus layer near the top, widest over the storm; the eye stays open
    // to the top, as satellite images show it.
    const double outflow = 0.18 * std::exp(-std::pow((height - 0.85) / 0.07, 2.0)) * smoothstep(0.09, 0.15, r) *
                           (1.0 - smoothstep(0.2, 0.6, r));

    const double texture = 1.0 + 0.15 * ripple(position + glm::dvec3(0.02 * hours));
    return std::clamp(strength * (wall + bands + outflow) * texture, 0.0, 1.0);
}

}  // namespace hurricane
