// The benchmark's scaling run: the bouncing super-ellipsoid simulated for longer, so that n
// time-steps keep the bundled dataset's rate of 10 time-steps per 1.6 s, with boxes riding with the
// object (partial overlap) or on one common grid (full overlap).
#pragma once

#include <string>

#include "tstyles/data/series.h"

namespace tstyles::cli {

// The simulated seconds that n time-steps span at the bundled dataset's rate (step 10 at 1.6 s).
double scalingDuration(int steps);

// Builds the series in memory through a scratch folder that is removed again.
Series buildScalingSeries(int steps, bool aligned);

// The dataset's label in the benchmark table, e.g. "superellipsoid-x40".
std::string scalingDatasetName(int steps, bool aligned);

}  // namespace tstyles::cli
