// The histogram drawn behind the STF editor: how often each density occurs over all time-steps,
// on a log scale so that the rare densities of the features are not flattened by the background.
#pragma once

#include <vector>

#include "tstyles/data/series.h"

namespace tstyles::viewer {

struct DensityHistogram {
    std::vector<double> counts;  // samples per bin, densities [0, 1] in equal bins
    // log(1 + count) per bin, divided by the largest, so each is in [0, 1].
    std::vector<double> logHeights;
};

DensityHistogram computeDensityHistogram(const Series& series, int bins = 128);

}  // namespace tstyles::viewer
