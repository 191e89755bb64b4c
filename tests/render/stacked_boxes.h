// Shared by the compositor tests: constant boxes over one another, one per time-step, seen from
// above by a 64-pixel orthographic camera, with the pure colours an index TSTF gives each time-step
// and the tolerance their pixels are read back with.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render_test_support.h"

namespace tstyles::testing {

inline constexpr int kStackSize = 64;
inline constexpr double kStackViewHeight = 2.0;
inline const glm::dvec2 kStackCentre(0.35, 0.35);
// As in analytic_render_test.cpp: densities through 16-bit textures, transfer functions through
// 1024-entry tables, float arithmetic along the ray.
inline constexpr float kStackTolerance = 2e-3f;

inline const glm::vec4 kRed{1, 0, 0, 1};
inline const glm::vec4 kGreen{0, 1, 0, 1};
inline const glm::vec4 kBlue{0, 0, 1, 1};
inline const glm::vec4 kTransparent{0, 0, 0, 0};

// Boxes over one another at the origin, one per time-step, with these densities.
Series stackedBoxes(const std::vector<float>& densities);

// The pixel of `image` is `expected`, within kStackTolerance.
void expectPixelNear(const Image& image, glm::ivec2 pixel, glm::vec4 expected, const std::string& what);
// The pixel of `image` at world point `world` (seen by the stack's camera) is `expected`.
void expectStackPixel(const Image& image, glm::dvec2 world, glm::vec4 expected, const std::string& what);

}  // namespace tstyles::testing
