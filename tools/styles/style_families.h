// The families the built-in styles are made of: each takes a base colour and a normal.
#pragma once

#include "shading.h"

namespace styles {

// Lambert diffuse over a little ambient light.
Rgba matte(const Rgb& albedo, const glm::dvec3& normal);

// Matte plus a white Blinn-Phong highlight.
Rgba glossy(const Rgb& albedo, const glm::dvec3& normal);

// Cel shading: the diffuse term cut into three hard bands, plus a hard highlight spot.
Rgba toon(const Rgb& albedo, const glm::dvec3& normal);

// Polished metal: the reflected studio environment, dimmed away from the light, and a sharp
// highlight.
Rgba metal(const Rgb& tone, const glm::dvec3& normal);

// Silhouette only: transparent facing the viewer, opaque toward the rim.
Rgba contour(const Rgb& ink, double shadingAmount, const glm::dvec3& normal);

// X-ray look: faint and nearly transparent in the middle, a bright glowing rim.
Rgba xrayGlow(const Rgb& glow, const glm::dvec3& normal);

}  // namespace styles
