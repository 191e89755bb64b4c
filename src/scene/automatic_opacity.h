// The automatic STF opacity (docs/automatic-scene.md): the background peak of the density
// histogram (air in CT, zeros around a scan) is transparent, and the opacity rises over a
// percentile window of the other values. Private to src/scene.
#pragma once

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

// Densities of every time-step (a regular subsample of large series), missing values left out.
OpacityWindow automaticOpacityWindow(const Series& series);

// The opacity nodes of that window: 0 below `low`, a ramp to `peak` at `high`, held above; 0 over
// the background peak wherever it lies.
std::vector<OpacityNode> opacityNodes(const OpacityWindow& window);

}  // namespace tstyles
