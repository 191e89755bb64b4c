// Portable draws from std::mt19937 (see sonar_random.h).
#include "sonar_random.h"

#include <cmath>
#include <numbers>

namespace sonar {

double SonarRandom::uniform() {
    // 32 random bits, offset by half a step: values in (0, 1), symmetric about 0.5.
    return (double(engine_()) + 0.5) / 4294967296.0;
}

double SonarRandom::normal() {
    const double radius = std::sqrt(-2.0 * std::log(uniform()));
    return radius * std::cos(2.0 * std::numbers::pi * uniform());
}

double SonarRandom::speckle(int looks) {
    double sum = 0.0;
    for (int look = 0; look < looks; ++look) sum -= std::log(uniform());
    return sum / double(looks);
}

std::uint32_t pingSeed(std::uint32_t base, int ping, std::uint32_t purpose) {
    // A fixed integer mix (splitmix-style) of the three parts.
    std::uint64_t value = (std::uint64_t(base) << 32) ^ (std::uint64_t(std::uint32_t(ping)) << 8) ^ purpose;
    value += 0x9E3779B97F4A7C15ull;
    value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9ull;
    value = (value ^ (value >> 27)) * 0x94D049BB133111EBull;
    value ^= value >> 31;
    return std::uint32_t(value & 0xFFFFFFFFull);
}

}  // namespace sonar
