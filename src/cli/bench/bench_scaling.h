// The benchmark's scaling run: n time-steps of the bouncing super-ellipsoid. Partial overlap: the
// simulation runs longer, so that n time-steps keep the bundled dataset's rate of 10 per 1.6 s, each
// in a box riding with the object. Full overlap: every time-step on the bundled 256x128x64 common
// grid over the bundled 1.6 s, n time-steps sampled more densely in time.
#pragma once

#include <string>

#include "tstyles/data/series.h"

namespace tstyles::cli {

// The simulated seconds that n partially overlapping time-steps span at the bundled dataset's rate
// (step 10 at 1.6 s).
double scalingDuration(int steps);

// Builds the series in memory through a scratch folder that is removed again.
Series buildScalingSeries(int steps, bool aligned);

// The dataset's label in the benchmark table, e.g. "superellipsoid-x40".
std::string scalingDatasetName(int steps, bool aligned);

}  // namespace tstyles::cli
