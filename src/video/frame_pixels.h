// Between the renderer's float images and the 8-bit pixels FFmpeg encodes and decodes.
#pragma once

#include <cstdint>
#include <vector>

#include "tstyles/image/image.h"

namespace tstyles::video {

// Packed 8-bit RGB, rows top to bottom: the image composited over black (with premultiplied
// alpha that is its colour as it is), clamped to [0, 1] and rounded.
std::vector<std::uint8_t> rgb8OverBlack(const Image& image);

// An image with alpha 1 from 8-bit RGBA rows `stride` bytes apart (FFmpeg pads its rows).
Image imageFromRgba8(const std::uint8_t* rows, int stride, int width, int height);

}  // namespace tstyles::video
