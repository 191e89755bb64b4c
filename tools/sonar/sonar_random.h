// Deterministic random numbers for the sonar generator. std::mt19937 is specified bit for bit by
// the standard, but the standard distributions are not, so uniform, normal and speckle draws are
// computed here from the raw 32-bit outputs: the same seed gives the same bytes on every platform.
#pragma once

#include <cstdint>
#include <random>

namespace sonar {

class SonarRandom {
public:
    explicit SonarRandom(std::uint32_t seed) : engine_(seed) {}

    // Uniform in (0, 1): never exactly 0, so logarithms of it are finite.
    double uniform();
    // Uniform in [low, high).
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
    // Standard normal (Box-Muller; one of the pair is used).
    double normal();
    // Multi-look speckle: the mean of `looks` unit exponentials (a gamma variate with mean 1).
    double speckle(int looks);

private:
    std::mt19937 engine_;
};

// A seed for one purpose of one ping, so that ping p's bytes do not depend on how many pings are
// generated after it.
std::uint32_t pingSeed(std::uint32_t base, int ping, std::uint32_t purpose);

}  // namespace sonar
