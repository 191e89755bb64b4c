// The shared key light and the shading terms the style families are built from.
#include "shading.h"

#include <algorithm>
#include <cmath>

namespace styles {

namespace {
const glm::dvec3 kTowardViewer{0.0, 0.0, 1.0};
}  // namespace

glm::dvec3 keyLightDirection() { return glm::normalize(glm::dvec3(-1.0, 1.0, 1.6)); }

double lambert(const glm::dvec3& normal) { return std::max(0.0, glm::dot(normal, keyLightDirection())); }

double blinnPhong(const glm::dvec3& normal, double exponent) {
    const glm::dvec3 halfway = glm::normalize(keyLightDirection() + kTowardViewer);
    return std::pow(std::max(0.0, glm::dot(normal, halfway)), exponent);
}

double facingAway(const glm::dvec3& normal) { return 1.0 - std::clamp(normal.z, 0.0, 1.0); }

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

double silhouetteRadius(const glm::dvec3& normal) { return std::hypot(normal.x, normal.y); }

double studioReflection(const glm::dvec3& normal) {
    // Mirror the view ray; its height says whether it sees sky, the horizon or the floor. The
    // horizon sits a little below the equator, as on a photographed ball seen slightly from above.
    const glm::dvec3 reflected = 2.0 * normal.z * normal - kTowardViewer;
    const double height = reflected.y;
    constexpr double horizon = -0.2;
    if (height >= horizon) {
        // Brightest just above the horizon, deepening toward the zenith, as an overcast sky.
        const double skyward = (height - horizon) / (1.0 - horizon);
        return 0.98 - 0.4 * std::sqrt(skyward);
    }
    // A thin dark band right under the horizon, then a floor that brightens toward the nadir.
    const double belowHorizon = (horizon - height) / (1.0 + horizon);
    if (belowHorizon < 0.1) return 0.08;
    return 0.24 + 0.5 * belowHorizon;
}

}  // namespace styles
