// Picking in the volume: the world position of the first visible sample under a pixel, and the
// temporal profile there (the n densities over time). GL-free: it marches the same ray the
// raycaster would, on the CPU.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"

namespace tstyles::viewer {

// A sample counts as visible once some time-step's STF opacity there reaches this.
inline constexpr double kVisibleOpacity = 0.05;

struct Pick {
    glm::dvec2 pixel{0.0};  // where it was picked, pixels from the top left of the view
    glm::dvec3 world{0.0};
    std::vector<std::optional<double>> densities;  // one per time-step; none outside its grid
};

// Marches the ray through the pixel centre with `stepLength` from where it enters the series'
// bounds. None if the ray leaves the data without meeting a visible sample.
std::optional<Pick> pickFirstVisibleSample(const Series& series, const Scene& scene, glm::dvec2 pixel,
                                           glm::ivec2 viewport, double stepLength);

}  // namespace tstyles::viewer
