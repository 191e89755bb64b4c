// The automatic scene's ray step: from the data's own cell size, not its finest cell
// (docs/automatic-scene.md, "Ray step").
#pragma once

#include <optional>

#include "tstyles/data/display_frame.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/ray_modes.h"

namespace tstyles {

// The series' typical cell size in display units, times the ray mode's automaticStepInCells (one
// for composited rays, a half for the others): per grid axis the lower quartile of the distances
// between neighbouring nodes (the spacing of an even axis), the smallest over the axes and
// time-steps. A composited ray's opacity is corrected to its step, so a whole cell changes the
// picture little where half a cell took twice the samples: on the bundled hurricane at 512 x 512
// SSIM 0.998 (max 27/255 on 8.7 % of the pixels beyond 1/255), the super-ellipsoid 0.99995, a CT
// phantom and a CT perfusion series 0.993 and 0.992 (their noise's speckle). At half a cell, on
// even grids it is the renderer's default, half the finest spacing; on uneven
// levels (ocean depths, pressure levels) it samples as densely as three cells in four need, where
// the default took the one thinnest level (a few metres at the surface under levels of hundreds)
// and sampled every ray several times more finely. The median was tried: on the ocean eddy it
// blurred the surface's thin top levels visibly (max 90/255 against the exact step; the lower
// quartile 50/255, mean 0.105/255, SSIM 0.998). A beam grid (a sonar's fans) takes one range
// cell in every mode: its cells are far wider across the beams than along them (0.09 along the range
// of the bundled survey, about 2.6 across at mid-range), and half a range cell doubled the samples
// for a picture one cannot tell apart (max 19/255 in the seabed's speckle, mean 0.15/255 at 512 x
// 512). None for structured grids (the default stays). Opacity is corrected to the finest spacing
// either way, so the picture's opacity does not change with the step.
std::optional<double> automaticStep(const Series& series, const DisplayFrame& frame, RayMode mode);

}  // namespace tstyles
