// Screenshots of the volume area: the pixels the window shows there, read back from the frame
// being drawn after the volume is in place and before the panels and overlay go on top.
#pragma once

#include <glm/glm.hpp>

#include "tstyles/image/image.h"

namespace tstyles::viewer {

// Reads `size` pixels at `offset` (from the bottom left) of the window's back buffer, rows top to
// bottom, opaque (the window has no alpha to give).
Image captureWindowRegion(glm::ivec2 offset, glm::ivec2 size);

}  // namespace tstyles::viewer
