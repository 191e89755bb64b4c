// The part of a series that a scene's STF leaves visible: what an automatic camera frames
// (Framing::Visible), so that empty or transparent space (air around a scan, missing land) does
// not push the data into a corner of the picture. GL-free.
#pragma once

#include "tstyles/data/series.h"
#include "tstyles/scene/transfer_function.h"

namespace tstyles {

// World bounds of the voxels whose density the STF gives any opacity (missing values excluded),
// over all time-steps: per rectilinear time-step the box of such voxels' indices, turned into the
// world; for other grids the whole time-step when any of its voxels is visible. With nothing
// visible, the bounds of the whole series.
Bounds visibleBounds(const Series& series, const Stf& stf);

}  // namespace tstyles
