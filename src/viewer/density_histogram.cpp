// Counting densities into bins and putting the counts on a log scale.
#include "density_histogram.h"

#include <algorithm>
#include <cmath>

namespace tstyles::viewer {

DensityHistogram computeDensityHistogram(const Series& series, int bins) {
    DensityHistogram histogram;
    bins = std::max(bins, 1);
    histogram.counts.assign(std::size_t(bins), 0.0);
    for (const TimeStep& step : series.steps)
        for (const float density : step.density) {
            if (isMissing(density)) continue;  // no data is not a density
            const int bin = std::clamp(int(double(density) * bins), 0, bins - 1);
            histogram.counts[std::size_t(bin)] += 1.0;
        }
    histogram.logHeights.resize(histogram.counts.size());
    double highest = 0.0;
    for (std::size_t i = 0; i < histogram.counts.size(); ++i) {
        histogram.logHeights[i] = std::log1p(histogram.counts[i]);
        highest = std::max(highest, histogram.logHeights[i]);
    }
    if (highest > 0.0)
        for (double& height : histogram.logHeights) height /= highest;
    return histogram;
}

}  // namespace tstyles::viewer
