// The typical largest change over time of a series' visible places: what the gradient TSTF's
// automatic range reaches (docs/automatic-scene.md). Its parts are public so that processes that
// each hold one block of a series can take the changes of their own places and gather them
// (src/distributed); the result is then one process's.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/scene/transfer_function.h"

namespace tstyles {

// Whether every time-step is rectilinear on one grid and placement: the changes are then taken
// per node, else at the points of a lattice over the visible bounds.
bool sharesOneGrid(const Series& series);

// On a shared grid, the nodes whose change is taken: multiples of this linear index (every node of
// a grid of at most 1 M nodes). From the grid's size, so an outline (no values) gives it too.
std::size_t changeNodeStride(const Series& series);

// Otherwise, the places whose change is taken: a lattice of 32 points per axis over `visible`.
std::vector<glm::dvec3> changeLatticePoints(const Bounds& visible);

// A place's densities over time (missing ones included): one change (max - min) appended to
// `changes` where the STF shows at least one of them and two have data.
void addChange(const std::vector<double>& densities, const Stf& stf, std::vector<double>& changes);

// The change below which 99 % of `changes` lie, within [1e-3, 1]; 1 where there are none.
double typicalOf(std::vector<double> changes);

// Every visible place's change over the whole series (a series of fewer than two time-steps has
// none): the nodes of a shared grid, else the lattice over visibleBounds.
std::vector<double> temporalChanges(const Series& series, const Stf& stf);

}  // namespace tstyles
