// A block of a beam (sonar) grid: the beams and range bins whose cells meet a box, and the beam
// grid of just those nodes (series_crop.h cuts a sonar ping to one process's block with them).
// GL-free.
#pragma once

#include "tstyles/data/node_block.h"
#include "tstyles/data/series.h"

namespace tstyles {

// The nodes (azimuth beam, elevation beam, range bin) of the cells of `grid` that meet the
// grid-local box `local`, widened by `ghostNodes` on each side and clamped to the grid; at least
// two nodes along each axis that has two. A cell counts where the box meets its corners' bounding
// box grown by how far its curved faces bulge beyond them (the sagitta of its widest angle), so no
// cell that reaches into the box is left out. Where no cell meets the box: the first cell.
NodeBlock beamNodesMeeting(const BeamGrid& grid, const Bounds& local, int ghostNodes);

// The beam grid of `nodes`: their beams' angles and their range bins, so that every kept node
// keeps its position (to rounding in the range spacing).
BeamGrid cutBeamGrid(const BeamGrid& grid, const NodeBlock& nodes);

}  // namespace tstyles
