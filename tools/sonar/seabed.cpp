// Seabed depth and echo (see seabed.h).
#include "seabed.h"

#include <algorithm>
#include <cmath>

namespace sonar {
namespace {

constexpr double kPeakIntensity = 2.0;     // the floor's echo, stronger than the densest school
constexpr double kPeakWidth = 0.35;        // metres: half the pulse length smeared along range
constexpr double kSedimentIntensity = 0.2; // just below the floor
constexpr double kSedimentDecay = 2.5;     // metres for the sediment echo to fall by e

}  // namespace

double seabedDepth(double x, double z) {
    return 88.0 + 3.0 * std::sin(x / 19.0 + 0.7) + 2.0 * std::sin(z / 11.0) + 1.2 * std::sin((x + z) / 7.0);
}

double seabedEcho(const glm::dvec3& world, const glm::dvec3& beam, double range, double beamWidthRad) {
    const double below = -world.y - seabedDepth(world.x, world.z);  // metres under the floor
    // The footprint's spread in depth: half the beam's width (about its Gaussian sigma) at this
    // range times the tangent of its angle from straight down (the floor's own slope is left out).
    const double down = std::clamp(-beam.y, 0.1, 1.0);
    const double spread = 0.5 * range * beamWidthRad * std::sqrt(1.0 - down * down) / down;
    const double width = std::sqrt(kPeakWidth * kPeakWidth + spread * spread);
    const double peak = kPeakIntensity * std::exp(-0.5 * (below / width) * (below / width));
    const double sediment = below > 0.0 ? kSedimentIntensity * std::exp(-below / kSedimentDecay) : 0.0;
    return peak + sediment;
}

}  // namespace sonar
