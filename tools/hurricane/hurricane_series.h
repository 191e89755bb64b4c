// Samples the analytic hurricane into a series: 125 x 125 x 25 samples per time-step on one
// common grid, uneven pressure-like levels (dense near the surface), uint8 cloud water, and land
// below the terrain height marked as missing.
#pragma once

#include "tstyles/data/manifest.h"

namespace hurricane {

struct HurricaneSeriesOptions {
    int steps = 10;           // time-steps, uniform over 48 hours
    glm::ivec3 dims{125, 125, 25};
};

// The raw value that marks land (no atmosphere, so no cloud water): above every data value.
inline constexpr double kLandMarker = 255.0;

// uint8 cloud water 0..254 (value range [0, 254]), missing value 255; times in hours.
tstyles::RawSeries buildHurricaneSeries(const HurricaneSeriesOptions& options);

// The grid-local heights of the levels: gaps growing linearly from the surface up to kTopHeight.
std::vector<double> levelHeights(int levels);

}  // namespace hurricane
