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
#include "tstyles/scene/scene.h"
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
    // Of the places visible in at least half of their values: the standard deviation of the noise
    // in their densities (noiseOfPlace), and their mean density.
    std::vector<double> noises;
    std::vector<double> noiseDensities;
};

// The density bands of UnchangedTime's fitted thresholds, and the band of a density.
inline constexpr int kUnchangedDensityBands = 16;
int unchangedDensityBand(double density);
// A band's own noise is taken from this many places with noise up, in series of this many
// time-steps up; else the median of all places. With three time-steps one step (40, 40, 120: a
// lesion that grows) is as large as its noise estimate, and the places a change passes through
// fill the bands between the two values: their noise would be the change's. From four up, a place
// that steps once has a median first difference of 0.
inline constexpr std::size_t kFewestPlacesPerBand = 32;
inline constexpr std::size_t kFewestStepsForBands = 4;

// The standard deviation of independent noise on a place's densities (in time order, with data),
// told apart from real change by taking the smallest of robust estimates: the median absolute
// first difference (0 where the place holds one value most of the time: an event, a passing body),
// the median absolute second difference (0 where it changes linearly: a trend; from three values
// up), and from eleven values up the third and fourth (a season sampled monthly: its k-th
// differences shrink as (2 sin(pi / 12))^k = 0.52^k of its amplitude, noise's grow as sqrt C(2k, k),
// so that its second differences alone read a twelfth of its amplitude as noise and made the
// neighbouring months of its peak tie), each divided by what it is for Gaussian noise of standard
// deviation 1. Over many places the median of this estimate is 0.8 to 1.0 of the noise's standard
// deviation (measured in tests/model/unchanged_threshold_test.cpp), so that the places' median
// noise is the data's noise wherever fewer than half of the places hold an event or a jump.
double noiseOfPlace(const std::vector<double>& densities);

// A place's densities over time (missing ones included): where the STF shows at least one of them
// and two have data, its change (max - min) appended to `places.changes`, and where the STF shows
// at least half of them, its noise to `places.noises`.
void addChange(const std::vector<double>& densities, const Stf& stf, PlaceChanges& places);

// The change below which 99 % of `changes` lie, within [1e-3, 1]; 1 where there are none.
double typicalOf(std::vector<double> changes);

// The automatic thresholds of UnchangedTime for a series of `stepCount` time-steps
// (docs/automatic-scene.md): `below`, the change up to which a place is unchanged, is a tenth of the
// typical largest change, or more where the noise needs it: the range that the places' median
// noise reaches over `stepCount` values at most once in a hundred; `tie`, the difference up to which
// two time-steps tie, is what that noise puts between two equal values at most once in a hundred.
// `gain` is the ratio of the ray lengths through all visible places and through the changing ones
// (the cube root of their numbers), within [1, 8], so that a ray through the changing places
// gathers about the opacity that one through all of them did. The same thresholds per density band,
// from the noise of the places whose mean density is in the band, go into `belowByDensity` and
// `tieByDensity`.
struct UnchangedFit {
    double below = 0.0;
    double tie = 0.0;
    double gain = 1.0;
    double boundary = 0.0;  // from the value gradient: boundaryGradientOf (boundary_gradient.h)
    std::vector<double> belowByDensity;
    std::vector<double> tieByDensity;
};
UnchangedFit unchangedFitOf(const PlaceChanges& places, std::size_t stepCount);
// `unchanged`'s thresholds set to the fit, and back.
void takeFit(UnchangedTime& unchanged, const UnchangedFit& fit);
UnchangedFit fittedOf(const UnchangedTime& unchanged);

// The range that `count` independent standard normal values exceed with probability 0.01.
double noiseRangeQuantile(std::size_t count);

// Every visible place's change over the whole series (a series of fewer than two time-steps has
// none): the nodes of a shared grid, else the lattice over visibleBounds.
PlaceChanges temporalChanges(const Series& series, const Stf& stf);

}  // namespace tstyles
