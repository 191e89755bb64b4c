// One block of a series: every time-step cut to the nodes that a world box needs, with ghost nodes
// around it, for distributed (sort-last) rendering, where each process keeps only its block.
#pragma once

#include <cstddef>
#include <optional>

#include "tstyles/data/node_block.h"
#include "tstyles/data/series.h"

namespace tstyles {

// Every time-step keeps the nodes of the cells that `box` touches plus `ghostNodes` more on each
// side (clamped to its grid), so that trilinear samples and central-difference gradients anywhere
// inside `box` read exactly what they read in the whole series. A time-step that misses the box
// keeps two nodes per axis at its edge nearest to it (it stays in the series: time-step indices
// mean something to the index TSTF and the compositors). Values, masks, times and metadata carry
// over. A beam (sonar) time-step keeps the beams and range bins whose cells meet the box, plus the
// ghost nodes (beam_grid_block.h). A structured time-step is kept whole: its index axes do not run
// along the world's, and time-steps share one grid (and its inverse map); the renderer's clip box
// still gives each process only its block's samples of it, so the work splits but its memory does
// not. Takes the series by value so that a caller who moves it in never holds the whole and the
// block at once.
Series cropSeriesToBox(Series series, const Bounds& box, int ghostNodes);

// The same for one time-step, in place.
void cropTimeStepToBox(TimeStep& step, const Bounds& box, int ghostNodes);

// The nodes cropTimeStepToBox keeps of `step`, from its grid and placement alone (no values
// needed); none for a time-step kept whole. What a reader that reads only a block's values asks
// before it opens the files (readManifestBlock).
std::optional<NodeBlock> nodesKeptOf(const TimeStep& step, const Bounds& box, int ghostNodes);

// The grid and placement part of cropTimeStepToBox, for a time-step whose values (and mask) were
// read as nodesKeptOf's block already; std::logic_error if they were not.
void cropTimeStepGridToBox(TimeStep& step, const Bounds& box, int ghostNodes);

// The voxels cropTimeStepToBox keeps of `step` (nodesKeptOf's, or the whole grid's): what a
// reader that reads only a block checks against the memory cap.
std::size_t croppedVoxelCount(const TimeStep& step, const Bounds& box, int ghostNodes);

}  // namespace tstyles
