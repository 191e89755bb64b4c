// The automatic STF opacity (docs/automatic-scene.md): the background peak of the density
// histogram (air in CT, zeros around a scan) is transparent, and the opacity rises over a
// percentile window of the other values. The histogram's parts are public so that processes that
// each hold one block of a series can count their share and sum the counts (src/distributed).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/data/series.h"
#include "tstyles/scene/transfer_function.h"

namespace tstyles {

struct OpacityWindow {
    double low = 0.0;   // density at the window's lower percentile (opacity 0 there)
    double high = 1.0;  // density at its upper percentile (opacity `peak` there)
    double peak = 1.0;  // the most opaque value of the ramp
    // The background peak's density interval, when the histogram has one.
    std::optional<std::array<double, 2>> background;
    double backgroundFraction = 0.0;  // of all values with data
};

// The histogram's bins over densities 0..1.
inline constexpr int kOpacityHistogramBins = 1024;
int opacityHistogramBin(float density);

// Of each time-step the histogram counts the values at multiples of this linear index: every
// value of a series of at most 8 M values, a regular subsample of larger ones. From the grids'
// sizes, so a series' outline (no values) gives it too.
std::size_t opacityHistogramStride(const Series& series);

// The window of a histogram (kOpacityHistogramBins counts, missing values left out) of a series
// whose time-steps hold `voxelsPerStep` voxels on average.
OpacityWindow opacityWindowOf(std::vector<double> counts, std::size_t voxelsPerStep);
std::size_t averageVoxelsPerStep(const Series& series);  // from the grids' sizes, as the stride

// Densities of every time-step (a regular subsample of large series), missing values left out.
OpacityWindow automaticOpacityWindow(const Series& series);

// The opacity nodes of that window: 0 below `low`, a ramp to `peak` at `high`, held above; 0 over
// the background peak wherever it lies.
std::vector<OpacityNode> opacityNodes(const OpacityWindow& window);

}  // namespace tstyles
