// Testing whether a series' densities survive a smaller storage precision unchanged.
#include "tstyles/render/lossless_precision.h"

#include <algorithm>
#include <cmath>

namespace tstyles {
namespace {

// The value the GPU reads for `density` stored at `precision` (unorm: k / (2^bits - 1)).
double storedValue(float density, DensityPrecision precision) {
    const double clamped = std::clamp(double(density), 0.0, 1.0);
    switch (precision) {
        case DensityPrecision::Bits8:
            return std::round(clamped * 255.0) / 255.0;
        case DensityPrecision::Bits16:
            return std::round(clamped * 65535.0) / 65535.0;
        case DensityPrecision::Bits32:
            break;
    }
    return double(float(clamped));
}

// Below a sixtieth of a 16-bit step; the only differences above it between two unorm precisions
// are whole quantisation steps of the coarser one.
constexpr double kSameValue = 1e-6;

int bitsOf(DensityPrecision precision) {
    return precision == DensityPrecision::Bits8 ? 8 : precision == DensityPrecision::Bits16 ? 16 : 32;
}

}  // namespace

bool holdsExactly(const Series& series, DensityPrecision requested, DensityPrecision smaller) {
    for (const TimeStep& step : series.steps)
        for (const float density : step.density)
            if (!isMissing(density) &&
                std::abs(storedValue(density, requested) - storedValue(density, smaller)) > kSameValue)
                return false;
    return true;
}

std::vector<DensityPrecision> losslessSmallerPrecisions(const Series& series, DensityPrecision requested) {
    std::vector<DensityPrecision> result;
    for (DensityPrecision smaller : {DensityPrecision::Bits16, DensityPrecision::Bits8})
        if (bitsOf(smaller) < bitsOf(requested) && holdsExactly(series, requested, smaller)) result.push_back(smaller);
    return result;
}

}  // namespace tstyles
