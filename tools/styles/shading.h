// The lighting every built-in style shares: one key light from the upper left front, seen from the
// viewer on +z, so that styles used side by side agree on where the light is (the paper's caveat on
// inconsistent lit spheres, section 7).
#pragma once

#include <glm/glm.hpp>

namespace styles {

using Rgb = glm::dvec3;

// A style's value at one normal: display colour (not premultiplied) and the opacity factor.
struct Rgba {
    Rgb color{0.0};
    double alpha = 1.0;
};

// Unit vector toward the key light: up, to the left and toward the viewer.
glm::dvec3 keyLightDirection();

// Lambert term max(0, n·l) for the key light.
double lambert(const glm::dvec3& normal);

// Blinn-Phong term max(0, n·h)^exponent, h halfway between the key light and the viewer (+z).
double blinnPhong(const glm::dvec3& normal, double exponent);

// Fresnel-like rim term: 0 facing the viewer, 1 at the silhouette.
double facingAway(const glm::dvec3& normal);

double smoothstep(double edge0, double edge1, double x);

// Radius in the image plane, |n.xy|: 0 at the centre of the sphere, 1 on its silhouette.
double silhouetteRadius(const glm::dvec3& normal);

// Grey level of a studio environment (bright sky, dark horizon line, dim floor) reflected about
// the normal: what a polished metal ball shows.
double studioReflection(const glm::dvec3& normal);

}  // namespace styles
