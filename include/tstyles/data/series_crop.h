// One block of a series: every time-step cut to the nodes that a world box needs, with ghost nodes
// around it, for distributed (sort-last) rendering, where each process keeps only its block.
#pragma once

#include "tstyles/data/series.h"

namespace tstyles {

// Every time-step keeps the nodes of the cells that `box` touches plus `ghostNodes` more on each
// side (clamped to its grid), so that trilinear samples and central-difference gradients anywhere
// inside `box` read exactly what they read in the whole series. A time-step that misses the box
// keeps two nodes per axis at its edge nearest to it (it stays in the series: time-step indices
// mean something to the index TSTF and the compositors). Values, masks, times and metadata carry
// over. Rectilinear grids only: a beam or structured time-step is an InputError naming it. Takes
// the series by value so that a caller who moves it in never holds the whole and the block at once.
Series cropSeriesToBox(Series series, const Bounds& box, int ghostNodes);

}  // namespace tstyles
