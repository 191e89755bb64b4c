// Images as ImGui textures want them: 8-bit RGBA with straight (not premultiplied) alpha.
#pragma once

#include <cstdint>
#include <vector>

#include "tstyles/image/image.h"

namespace tstyles::viewer {

std::vector<std::uint8_t> straightBytes(const Image& image);

}  // namespace tstyles::viewer
