// One ping's echo volume on its beam grid: fish echoes smeared by the beam pattern and the pulse
// length, the seabed, a weak water-column background, range attenuation, speckle and receiver
// noise, stored as uint16 echo amplitudes; and the school's segmentation mask on the same samples.
#pragma once

#include <cstdint>
#include <vector>

#include "fish_school.h"
#include "tstyles/data/series.h"

namespace sonar {

// Stored values are echo amplitudes, the square root of the intensity, with kFullScale (about
// the seabed's echo) at 65535. An amplitude scale keeps the school's fluctuations proportional
// to its density, so its dense core changes most from ping to ping (paper, section 6); decibels
// would make every part of the school change alike.
constexpr double kFullScale = 0.5;
std::uint16_t intensityToValue(double linearIntensity);

struct PingEchoes {
    std::vector<std::uint16_t> values;  // i fastest, then j, then k (as the manifest stores them)
    std::vector<std::uint8_t> mask;    // 255 inside the school's envelope (radius <= kMaskRadius)
};

// Samples whose envelope radius is at most this are in the mask: a little more than the envelope,
// so the smeared echoes of the outermost fish are inside too.
constexpr double kMaskRadius = 1.1;

// `fish` are world positions with their strengths in `school`; `speckleSeed` drives the noise.
PingEchoes synthesizePing(const tstyles::BeamGrid& grid, const tstyles::Placement& pose,
                          const SchoolShape& shape, const std::vector<Fish>& school,
                          const std::vector<glm::dvec3>& fishWorld, std::uint32_t speckleSeed);

}  // namespace sonar
