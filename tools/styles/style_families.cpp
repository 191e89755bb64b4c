// Shading recipes for the style families; the constants are tuned by eye on the docs' pictures.
#include "style_families.h"

#include <algorithm>
#include <cmath>

namespace styles {

namespace {

constexpr double kAmbient = 0.22;
const Rgb kWhite{1.0};

Rgb diffuse(const Rgb& albedo, const glm::dvec3& normal) {
    return albedo * (kAmbient + (1.0 - kAmbient) * lambert(normal));
}

Rgba opaque(const Rgb& color) { return {glm::clamp(color, 0.0, 1.0), 1.0}; }

}  // namespace

Rgba matte(const Rgb& albedo, const glm::dvec3& normal) { return opaque(diffuse(albedo, normal)); }

Rgba glossy(const Rgb& albedo, const glm::dvec3& normal) {
    const double highlight = 0.85 * blinnPhong(normal, 60.0);
    return opaque(glm::mix(diffuse(albedo, normal), kWhite, highlight));
}

Rgba toon(const Rgb& albedo, const glm::dvec3& normal) {
    // Hard thresholds on purpose: the rasteriser's supersampling is what smooths the band edges.
    const double light = lambert(normal);
    double level = 0.38;
    if (light > 0.25) level = 0.68;
    if (light > 0.7) level = 1.0;
    Rgb color = albedo * level;
    if (blinnPhong(normal, 60.0) > 0.55) color = glm::mix(albedo, kWhite, 0.7);
    return opaque(color);
}

Rgba metal(const Rgb& tone, const glm::dvec3& normal) {
    const double environment = studioReflection(normal) * (0.6 + 0.4 * lambert(normal));
    const double highlight = blinnPhong(normal, 150.0);
    return opaque(glm::mix(tone * environment, kWhite, highlight));
}

Rgba contour(const Rgb& ink, double shadingAmount, const glm::dvec3& normal) {
    const double shade = 1.0 - shadingAmount + shadingAmount * lambert(normal);
    return {ink * shade, smoothstep(0.55, 0.9, silhouetteRadius(normal))};
}

Rgba xrayGlow(const Rgb& glow, const glm::dvec3& normal) {
    const double rim = std::pow(facingAway(normal), 0.9);
    const Rgb color = glm::mix(0.35 * glow, glm::mix(glow, kWhite, 0.5), rim);
    return {glm::clamp(color, 0.0, 1.0), 0.06 + 0.94 * rim};
}

}  // namespace styles
