// A GIF frame's 256-colour palette, built per frame by median cut over the frame's own colours.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tstyles::video {

struct PalettedFrame {
    // 0xAARRGGBB, as FFmpeg's PAL8 frames hold it; unused entries are opaque black.
    std::array<std::uint32_t, 256> palette{};
    std::vector<std::uint8_t> indices;  // one per pixel, rows top to bottom
};

// `rgb`: width * height packed 8-bit RGB triples. A frame with at most 256 colours keeps every
// colour exactly; one with more gets a median-cut palette and Floyd-Steinberg dithering, which
// trades banding in the renderer's smooth gradients for fine noise.
PalettedFrame palettize(std::span<const std::uint8_t> rgb, int width, int height);

}  // namespace tstyles::video
