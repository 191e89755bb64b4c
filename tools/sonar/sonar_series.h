// The synthetic sonar survey as a series: one beam grid per ping (25 x 20 beams x 1319 range
// samples by default) at the transducer's pose, uint16 echo amplitudes and a school mask per ping.
// Deterministic: fixed seeds, and ping p's bytes do not depend on how many pings follow it.
// docs/sonar-dataset.md describes the scene.
#pragma once

#include <cstdint>

#include "tstyles/data/manifest.h"

namespace sonar {

constexpr int kMaxPings = 75;

struct SonarSeriesOptions {
    int pings = 10;
    glm::ivec3 dims{25, 20, 1319};  // beams across, beams along, range samples
    int fishCount = 3000;
    std::uint32_t seed = 20090531u;
};

// The beam grid every ping uses: 60 x 40 degrees, ranges 2 to 120 m.
tstyles::BeamGrid surveyBeamGrid(const glm::ivec3& dims);

// Values in [0, 65535] (echo amplitudes, see ping_echoes.h); times in seconds.
tstyles::RawSeries buildSonarSeries(const SonarSeriesOptions& options);

}  // namespace sonar
