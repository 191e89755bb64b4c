// Float <-> 8-bit pixel conversion for movie frames.
#include "frame_pixels.h"

#include <algorithm>
#include <cmath>

namespace tstyles::video {

std::vector<std::uint8_t> rgb8OverBlack(const Image& image) {
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    std::vector<std::uint8_t> rgb(pixels * 3);
    for (std::size_t p = 0; p < pixels; ++p)
        for (std::size_t c = 0; c < 3; ++c) {
            // Over black, a premultiplied colour is what it is: c + (1 - a) * 0. A NaN becomes 0.
            const float raw = image.rgba[p * 4 + c];
            const float value = raw > 0.0f ? std::min(raw, 1.0f) : 0.0f;
            rgb[p * 3 + c] = std::uint8_t(std::lround(value * 255.0f));
        }
    return rgb;
}

Image imageFromRgba8(const std::uint8_t* rows, int stride, int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* row = rows + std::ptrdiff_t(y) * stride;
        for (int x = 0; x < width; ++x)
            image.set(x, y, {row[4 * x] / 255.0f, row[4 * x + 1] / 255.0f, row[4 * x + 2] / 255.0f, 1.0f});
    }
    return image;
}

}  // namespace tstyles::video
