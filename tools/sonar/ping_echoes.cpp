// Echo synthesis for one ping (see ping_echoes.h).
#include "ping_echoes.h"

#include <algorithm>
#include <cmath>

#include "seabed.h"
#include "sonar_random.h"
#include "tstyles/data/beam_geometry.h"

namespace sonar {
namespace {

constexpr double kFishIntensity = 0.004;         // one mean fish at the centre of its beam and range cell
constexpr double kBeamSigma = 0.6;               // beam pattern, in beam spacings (Gaussian)
constexpr double kPulseSigma = 0.25;             // metres along range (Gaussian)
constexpr double kWaterColumn = 1.0e-4;          // weak volume backscatter (-40 dB)
constexpr double kNoiseFloor = 1.5e-5;           // receiver noise (-48 dB), not attenuated
constexpr double kAttenuationDbPerMetre = 0.08;  // what is left after time-varied gain
constexpr int kSpeckleLooks = 6;

double attenuation(double range) { return std::pow(10.0, -0.1 * kAttenuationDbPerMetre * range); }

std::size_t sampleIndex(const glm::ivec3& dims, int i, int j, int k) {
    return std::size_t(i) + std::size_t(dims.x) * (std::size_t(j) + std::size_t(dims.y) * std::size_t(k));
}

// Fractional beam index of an angle among evenly or unevenly spread beams, extended linearly
// beyond the outermost beams (fish just outside the fan still reach its edge beams).
double beamCoordinate(const std::vector<double>& anglesDeg, double angleDeg) {
    if (angleDeg <= anglesDeg.front())
        return (angleDeg - anglesDeg.front()) / (anglesDeg[1] - anglesDeg[0]);
    if (angleDeg >= anglesDeg.back()) {
        const std::size_t last = anglesDeg.size() - 1;
        return double(last) + (angleDeg - anglesDeg[last]) / (anglesDeg[last] - anglesDeg[last - 1]);
    }
    return *tstyles::fractionalBeamIndex(anglesDeg, angleDeg);
}

// Adds every fish's echo to the samples its beam pattern and pulse reach.
void addFishEchoes(const tstyles::BeamGrid& grid, const tstyles::Placement& pose,
                   const std::vector<Fish>& school, const std::vector<glm::dvec3>& fishWorld,
                   std::vector<double>& intensity) {
    const glm::dquat worldToLocal = glm::conjugate(pose.rotation);
    const double reach = 3.0 * kBeamSigma;
    const double spacing = grid.rangeSpacing();
    for (std::size_t f = 0; f < school.size(); ++f) {
        const glm::dvec3 local = worldToLocal * (fishWorld[f] - pose.origin);
        if (!(local.z > 0.0)) continue;
        const double range = glm::length(local);
        const double across = beamCoordinate(grid.azimuthDeg, glm::degrees(std::atan2(local.x, local.z)));
        const double along = beamCoordinate(grid.elevationDeg, glm::degrees(std::atan2(local.y, local.z)));
        const int iFirst = std::max(0, int(std::ceil(across - reach)));
        const int iLast = std::min(grid.dims.x - 1, int(std::floor(across + reach)));
        const int jFirst = std::max(0, int(std::ceil(along - reach)));
        const int jLast = std::min(grid.dims.y - 1, int(std::floor(along + reach)));
        const double rangeIndex = (range - grid.minRange) / spacing;
        const double rangeReach = 4.0 * kPulseSigma / spacing;
        const int kFirst = std::max(0, int(std::ceil(rangeIndex - rangeReach)));
        const int kLast = std::min(grid.dims.z - 1, int(std::floor(rangeIndex + rangeReach)));
        const double strength = kFishIntensity * school[f].strength;
        for (int k = kFirst; k <= kLast; ++k) {
            const double dr = (grid.minRange + double(k) * spacing - range) / kPulseSigma;
            const double pulse = strength * std::exp(-0.5 * dr * dr);
            for (int j = jFirst; j <= jLast; ++j) {
                const double dj = (double(j) - along) / kBeamSigma;
                for (int i = iFirst; i <= iLast; ++i) {
                    const double di = (double(i) - across) / kBeamSigma;
                    intensity[sampleIndex(grid.dims, i, j, k)] += pulse * std::exp(-0.5 * (di * di + dj * dj));
                }
            }
        }
    }
}

}  // namespace

std::uint16_t intensityToValue(double linearIntensity) {
    const double amplitude = std::sqrt(std::clamp(linearIntensity / kFullScale, 0.0, 1.0));
    return static_cast<std::uint16_t>(std::lround(65535.0 * amplitude));
}

PingEchoes synthesizePing(const tstyles::BeamGrid& grid, const tstyles::Placement& pose,
                          const SchoolShape& shape, const std::vector<Fish>& school,
                          const std::vector<glm::dvec3>& fishWorld, std::uint32_t speckleSeed) {
    std::vector<double> intensity(grid.voxelCount(), 0.0);
    addFishEchoes(grid, pose, school, fishWorld, intensity);

    PingEchoes echoes;
    echoes.values.resize(grid.voxelCount());
    echoes.mask.resize(grid.voxelCount());
    // The wider of the two beam spacings stands for the beam's width where it meets the seabed.
    const double beamWidth = glm::radians(std::max(grid.azimuthDeg[1] - grid.azimuthDeg[0],
                                                   grid.elevationDeg[1] - grid.elevationDeg[0]));
    // Each beam's unit direction in the grid's frame, taken at the far end where it is never zero.
    std::vector<glm::dvec3> beamAxes;
    for (int j = 0; j < grid.dims.y; ++j)
        for (int i = 0; i < grid.dims.x; ++i)
            beamAxes.push_back(glm::normalize(tstyles::beamSamplePosition(grid, i, j, grid.dims.z - 1)));
    SonarRandom random(speckleSeed);
    for (int k = 0; k < grid.dims.z; ++k) {
        const double range = grid.minRange + double(k) * grid.rangeSpacing();
        const double loss = attenuation(range);
        for (int j = 0; j < grid.dims.y; ++j)
            for (int i = 0; i < grid.dims.x; ++i) {
                const std::size_t index = sampleIndex(grid.dims, i, j, k);
                const glm::dvec3 axis = beamAxes[std::size_t(i) + std::size_t(grid.dims.x) * std::size_t(j)];
                const glm::dvec3 world = pose.origin + pose.rotation * (range * axis);
                const glm::dvec3 beam = pose.rotation * axis;
                const double echo = intensity[index] + seabedEcho(world, beam, range, beamWidth) + kWaterColumn;
                const double received = loss * echo * random.speckle(kSpeckleLooks) +
                                        kNoiseFloor * random.speckle(1);
                echoes.values[index] = intensityToValue(received);
                echoes.mask[index] = shape.normalisedRadius(world) <= kMaskRadius ? 255 : 0;
            }
    }
    return echoes;
}

}  // namespace sonar
