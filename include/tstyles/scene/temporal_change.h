// The typical largest change over time of a series' visible places: what the gradient TSTF's
// automatic range reaches; and the change below which a place counts as unchanged, so that a
// compositor that picks a time-step shows no time colour there (docs/automatic-scene.md). Their
// parts are public so that processes that each hold one block of a series can take the changes of
// their own places and gather them (src/distributed); the result is then one process's.
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

// The visible places' changes over time, and the noise in them.
struct PlaceChanges {
    std::vector<double> changes;  // each place's largest minus smallest density
    // Of the places with at least kFewestValuesForNoise values: the standard deviation of the noise
    // in their densities (noiseOfPlace).
    std::vector<double> noises;
};

// A place's noise is estimated from this many values with data up.
inline constexpr std::size_t kFewestValuesForNoise = 6;

// The standard deviation of independent noise on a place's densities (in time order, with data),
// told apart from real change by taking the smaller of two robust estimates: the median absolute
// first difference (0 where the place holds one value most of the time: an event, a passing body)
// and the median absolute second difference (about 0 where it changes smoothly: a trend, a season),
// each divided by what it is for Gaussian noise of standard deviation 1.
double noiseOfPlace(const std::vector<double>& densities);

// A place's densities over time (missing ones included): where the STF shows at least one of them
// and two have data, its change (max - min) appended to `places.changes`, and with
// kFewestValuesForNoise values its noise to `places.noises`.
void addChange(const std::vector<double>& densities, const Stf& stf, PlaceChanges& places);

// The change below which 99 % of `changes` lie, within [1e-3, 1]; 1 where there are none.
double typicalOf(std::vector<double> changes);

// The change below which a place is unchanged, in a series of `stepCount` time-steps: a tenth of
// the typical largest change, or more where the noise needs it: the change that the places' median
// noise reaches over `stepCount` values at most once in a hundred (docs/automatic-scene.md).
double unchangedThresholdOf(const PlaceChanges& places, std::size_t stepCount);

// The range that `count` independent standard normal values exceed with probability 0.01.
double noiseRangeQuantile(std::size_t count);

// Every visible place's change over the whole series (a series of fewer than two time-steps has
// none): the nodes of a shared grid, else the lattice over visibleBounds.
PlaceChanges temporalChanges(const Series& series, const Stf& stf);

}  // namespace tstyles
