// Draws a style into a square lit-sphere image, with the renderer's mapping: texel (u, v) shows the
// normal with n.x = 2u - 1 and n.y = 2v - 1, v up, so row 0 is the top of the sphere (n.y = +1).
#pragma once

#include <cstdint>
#include <vector>

#include "style_catalog.h"

namespace styles {

// 8-bit RGBA, straight (not premultiplied) alpha, rows top to bottom.
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// What texels off the unit disc hold.
enum class OutsideDisc {
    RimValue,     // the value on the rim at the same angle: for rendering
    Transparent,  // nothing: for pictures of the style
};

// Each texel averages 4 x 4 samples, so band and contour edges are anti-aliased. Samples outside
// the unit disc take the value on the rim at the same angle: the renderer never reads there, but
// mipmaps blend those texels into the rim, and a dark or transparent border would show as a halo.
RgbaImage rasterizeLitSphere(const StyleDefinition& style, int size,
                             OutsideDisc outside = OutsideDisc::RimValue);

}  // namespace styles
