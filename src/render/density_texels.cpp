// Densities quantised to 16 bits, premultiplied by validity when the series has missing values.
#include "tstyles/render/density_texels.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace tstyles {

bool hasMissingValues(const Series& series) {
    return std::any_of(series.steps.begin(), series.steps.end(), [](const TimeStep& step) {
        return std::any_of(step.density.begin(), step.density.end(), [](float d) { return isMissing(d); });
    });
}

std::vector<std::uint16_t> densityTexels(const TimeStep& step, bool withValidity) {
    const auto quantise = [](float density) {
        return std::uint16_t(std::lround(std::clamp(density, 0.0f, 1.0f) * 65535.0f));
    };
    std::vector<std::uint16_t> texels;
    texels.reserve(step.density.size() * (withValidity ? 2 : 1));
    for (const float density : step.density) {
        if (!withValidity) {
            texels.push_back(quantise(density));
            continue;
        }
        const bool valid = !isMissing(density);
        texels.push_back(valid ? quantise(density) : 0);
        texels.push_back(valid ? 65535 : 0);
    }
    return texels;
}

namespace {

template <typename Texel>
std::vector<std::uint8_t> texelBytes(const TimeStep& step, bool withValidity, float full) {
    const auto quantise = [full](float density) {
        const float clamped = std::clamp(density, 0.0f, 1.0f);
        if constexpr (std::is_floating_point_v<Texel>) return Texel(clamped);
        else return Texel(std::lround(clamped * full));
    };
    std::vector<Texel> texels;
    texels.reserve(step.density.size() * (withValidity ? 2 : 1));
    for (const float density : step.density) {
        const bool valid = !isMissing(density);
        if (!withValidity) {
            texels.push_back(quantise(valid ? density : 0.0f));
            continue;
        }
        texels.push_back(valid ? quantise(density) : Texel(0));
        texels.push_back(valid ? quantise(1.0f) : Texel(0));
    }
    std::vector<std::uint8_t> bytes(texels.size() * sizeof(Texel));
    std::memcpy(bytes.data(), texels.data(), bytes.size());
    return bytes;
}

}  // namespace

std::vector<std::uint8_t> densityTexelBytes(const TimeStep& step, bool withValidity, DensityPrecision precision) {
    switch (precision) {
        case DensityPrecision::Bits8:
            return texelBytes<std::uint8_t>(step, withValidity, 255.0f);
        case DensityPrecision::Bits16:
            return texelBytes<std::uint16_t>(step, withValidity, 65535.0f);
        case DensityPrecision::Bits32:
            break;
    }
    return texelBytes<float>(step, withValidity, 1.0f);
}

}  // namespace tstyles
