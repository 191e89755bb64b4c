// Supersampled rasterisation of a style over the lit-sphere disc.
#include "lit_sphere_raster.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace styles {

namespace {

constexpr int kSamplesPerAxis = 4;

// The normal a point of the image plane shows; points off the disc are pulled onto its rim, or
// show nothing.
std::optional<glm::dvec3> normalAt(double x, double y, OutsideDisc outside) {
    const double radius = std::hypot(x, y);
    if (radius < 1.0) return glm::dvec3(x, y, std::sqrt(1.0 - radius * radius));
    if (outside == OutsideDisc::Transparent) return std::nullopt;
    return glm::dvec3(x / radius, y / radius, 0.0);
}

std::uint8_t toByte(double value) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
}

// Averages the samples of one texel. Colours are weighted by alpha, as a filter over premultiplied
// colour would; texels that are transparent throughout keep the plain average colour, so that a
// contour style's centre still carries its ink colour.
Rgba sampleTexel(const StyleDefinition& style, int column, int row, int size, OutsideDisc outside) {
    Rgb weighted{0.0};
    Rgb plain{0.0};
    double alphaSum = 0.0;
    int shown = 0;
    for (int sy = 0; sy < kSamplesPerAxis; ++sy)
        for (int sx = 0; sx < kSamplesPerAxis; ++sx) {
            const double u = (column + (sx + 0.5) / kSamplesPerAxis) / size;
            const double fromTop = (row + (sy + 0.5) / kSamplesPerAxis) / size;
            const auto normal = normalAt(2.0 * u - 1.0, 1.0 - 2.0 * fromTop, outside);
            if (!normal) continue;
            const Rgba sample = style.shade(*normal);
            weighted += sample.color * sample.alpha;
            plain += sample.color;
            alphaSum += sample.alpha;
            ++shown;
        }
    constexpr double count = kSamplesPerAxis * kSamplesPerAxis;
    if (shown == 0) return {Rgb{0.0}, 0.0};
    const Rgb color = alphaSum > 1e-6 ? weighted / alphaSum : plain / double(shown);
    return {color, alphaSum / count};
}

}  // namespace

RgbaImage rasterizeLitSphere(const StyleDefinition& style, int size, OutsideDisc outside) {
    RgbaImage image{size, size, std::vector<std::uint8_t>(std::size_t(size) * std::size_t(size) * 4)};
    for (int row = 0; row < size; ++row)
        for (int column = 0; column < size; ++column) {
            const Rgba texel = sampleTexel(style, column, row, size, outside);
            std::uint8_t* out = &image.rgba[(std::size_t(row) * std::size_t(size) + std::size_t(column)) * 4];
            out[0] = toByte(texel.color.r);
            out[1] = toByte(texel.color.g);
            out[2] = toByte(texel.color.b);
            out[3] = toByte(texel.alpha);
        }
    return image;
}

}  // namespace styles
