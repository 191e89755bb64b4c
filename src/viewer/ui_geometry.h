// Screen rectangles in window coordinates (pixels, origin top left), shared by layout, anchors and
// widgets without tying them to ImGui's vector types.
#pragma once

#include <glm/glm.hpp>

namespace tstyles::viewer {

struct ScreenRect {
    glm::vec2 min{0.0f};
    glm::vec2 max{0.0f};

    glm::vec2 size() const { return max - min; }
    glm::vec2 center() const { return 0.5f * (min + max); }
    bool contains(glm::vec2 point) const {
        return point.x >= min.x && point.y >= min.y && point.x < max.x && point.y < max.y;
    }
    // The point at fractions (u, v) across the rectangle, (0, 0) top left.
    glm::vec2 at(glm::vec2 uv) const { return min + uv * size(); }
    bool operator==(const ScreenRect&) const = default;
};

}  // namespace tstyles::viewer
