// A palette of at most 256 colours for one GIF frame (the format's limit): a frame with that few
// colours keeps them exactly; others get a median-cut palette. Private to src/video.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace tstyles::video {

struct PalettedFrame {
    std::array<std::uint32_t, 256> palette{};  // 0xAARRGGBB, as libavcodec's PAL8 frames hold it
    std::vector<std::uint8_t> indices;         // one per pixel, rows top to bottom
};

// `rgb`: three bytes per pixel.
PalettedFrame paletteFrame(const std::vector<std::uint8_t>& rgb, int width, int height);

}  // namespace tstyles::video
