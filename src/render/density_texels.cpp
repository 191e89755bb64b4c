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
std::vector<std::uint8_t> texelBytes(const TimeStep& step, bool withValidity, bool withMask, float full) {
    const auto quantise = [full](float density) {
        const float clamped = std::clamp(density, 0.0f, 1.0f);
        if constexpr (std::is_floating_point_v<Texel>) return Texel(clamped);
        else return Texel(std::lround(clamped * full));
    };
    std::vector<Texel> texels;
    texels.reserve(step.density.size() * std::size_t(densityChannelCount(withValidity, withMask)));
    for (std::size_t voxel = 0; voxel < step.density.size(); ++voxel) {
        const float density = step.density[voxel];
        const bool valid = !isMissing(density);
        if (withValidity) {
            texels.push_back(valid ? quantise(density) : Texel(0));
            texels.push_back(valid ? quantise(1.0f) : Texel(0));
        } else {
            texels.push_back(quantise(valid ? density : 0.0f));
        }
        // Uploaded as 0 / full scale so that trilinear filtering gives a smooth boundary at 0.5.
        if (withMask) texels.push_back(!step.mask || (*step.mask)[voxel] != 0 ? quantise(1.0f) : Texel(0));
    }
    std::vector<std::uint8_t> bytes(texels.size() * sizeof(Texel));
    std::memcpy(bytes.data(), texels.data(), bytes.size());
    return bytes;
}

}  // namespace

int densityChannelCount(bool withValidity, bool withMask) { return 1 + (withValidity ? 1 : 0) + (withMask ? 1 : 0); }

std::vector<std::uint8_t> densityTexelBytes(const TimeStep& step, bool withValidity, bool withMask,
                                            DensityPrecision precision) {
    switch (precision) {
        case DensityPrecision::Bits8:
            return texelBytes<std::uint8_t>(step, withValidity, withMask, 255.0f);
        case DensityPrecision::Bits16:
            return texelBytes<std::uint16_t>(step, withValidity, withMask, 65535.0f);
        case DensityPrecision::Bits32:
            break;
    }
    return texelBytes<float>(step, withValidity, withMask, 1.0f);
}

}  // namespace tstyles
