// Picking in the volume: the world place a pixel shows, where the window's probe lands
// (docs/probe.md). GL-free: it marches the pixel's ray on the CPU and estimates from the STF where
// the picture's sample lies, by the ray mode's ProbeDepth (ray_modes.h).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"

namespace tstyles::viewer {

// The world place under `pixel` (pixels from the top left of a view of `viewport`), marching the
// ray through the pixel centre with `stepLength` from where it enters the series' bounds, over the
// exposed time-steps:
// - composited modes: where the opacity gathered along the ray first passes one half, each sample
//   as opaque as its most opaque time-step's STF makes it (an unchanged place scaled by the
//   unchanged share, a changing one thickened by the gain), corrected to the step as the raycaster
//   corrects it (`referenceLength`: its finest spacing);
// - maximum and minimum: the sample of the largest (smallest) density the STF shows;
// - largest change: the sample whose densities differ most over time;
// - iso-surfaces: the first place some time-step's density crosses an iso-value.
// None where the ray misses the data or meets nothing the mode would show.
std::optional<glm::dvec3> probePlaceUnder(const Series& series, const Scene& scene, glm::dvec2 pixel,
                                          glm::ivec2 viewport, double stepLength, double referenceLength);

}  // namespace tstyles::viewer
