// The part of a series that a scene's STF leaves visible: what an automatic camera frames
// (Framing::Visible), so that empty or transparent space (air around a scan, missing land) does
// not push the data into a corner of the picture. GL-free.
#pragma once

#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/scene/transfer_function.h"

namespace tstyles {

// A box of a grid's node indices, lower..upper inclusive; empty as made.
struct NodeIndexBox {
    glm::ivec3 lower{std::numeric_limits<int>::max()};
    glm::ivec3 upper{std::numeric_limits<int>::min()};
    bool empty() const { return lower.x > upper.x; }
};

// Per time-step, the box of the nodes whose density the STF gives any opacity (missing values
// excluded); empty where there is none, or the time-step holds no values (an outline).
std::vector<NodeIndexBox> visibleNodeBoxes(const Series& series, const Stf& stf);

// The world bounds of such boxes, one per time-step of `series` (whose values are not read, so an
// outline serves): a rectilinear time-step's box turned into the world, any other time-step's whole
// bounds where its box is not empty; with every box empty, the bounds of the whole series.
Bounds boundsOfVisibleNodes(const Series& series, const std::vector<NodeIndexBox>& boxes);

// World bounds of the voxels whose density the STF gives any opacity (missing values excluded),
// over all time-steps: per rectilinear time-step the box of such voxels' indices, turned into the
// world; for other grids the whole time-step when any of its voxels is visible. With nothing
// visible, the bounds of the whole series. boundsOfVisibleNodes(series, visibleNodeBoxes(series, stf)).
Bounds visibleBounds(const Series& series, const Stf& stf);

}  // namespace tstyles
