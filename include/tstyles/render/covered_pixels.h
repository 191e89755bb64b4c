// The pixels a world-space box can cover in a view: the raycasting pass runs only there (a scissor
// rectangle), the rest of the frame is the background, which is what a ray that meets no
// time-step gives anyway.
#pragma once

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

struct PixelRectangle {
    glm::ivec2 offset{0};
    glm::ivec2 size{0};
};

// A conservative rectangle around the projection of the box's eight corners, one pixel of margin,
// clamped to the viewport. The whole viewport when a corner lies at or behind the eye (w <= 0),
// where the projection of corners says nothing about the box.
PixelRectangle coveredPixels(const Bounds& box, const glm::dmat4& viewProjection, glm::ivec2 viewport);

}  // namespace tstyles
