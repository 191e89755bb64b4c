// Premultiplied float RGBA to straight 8-bit RGBA, for textures that ImGui blends.
#include "straight_bytes.h"

#include <algorithm>
#include <cmath>

namespace tstyles::viewer {

std::vector<std::uint8_t> straightBytes(const Image& image) {
    std::vector<std::uint8_t> bytes(image.rgba.size());
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        const float alpha = image.rgba[i + 3];
        for (std::size_t c = 0; c < 4; ++c) {
            const float value = c < 3 ? (alpha > 0.0f ? image.rgba[i + c] / alpha : 0.0f) : alpha;
            bytes[i + c] = std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
        }
    }
    return bytes;
}

}  // namespace tstyles::viewer
