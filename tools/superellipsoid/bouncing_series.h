// Turns the simulated bounce into a series: either one box per time-step riding with the object
// (partially overlapping, the paper's layout) or one common world grid for every time-step.
#pragma once

#include "tstyles/data/manifest.h"

namespace superellipsoid {

struct BouncingSeriesOptions {
    int steps = 10;        // time-steps, uniform in time over the simulated duration
    int resolution = 64;   // samples along each axis of a per-step box
    bool aligned = false;  // one common world grid instead of boxes riding with the object
    // Simulated seconds the time-steps span; a longer simulation keeps bouncing (the benchmark's
    // scaling run keeps the default's rate of 10 time-steps per 1.6 s).
    double duration = 1.6;
};

// uint8 densities with value range [0, 255]; time stamps are the simulated time in seconds.
tstyles::RawSeries buildBouncingSeries(const BouncingSeriesOptions& options);

}  // namespace superellipsoid
