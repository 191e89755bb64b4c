// Named places on screen that widgets publish every frame ("tstf" is the index TSTF's canvas,
// "volume" the volume area, ...), so that a test script can say "the node at time-step 3" instead
// of a pixel position that moves whenever the layout changes. A place is a rectangle and a mapping
// from two parameters to a pixel: fractions across the rectangle, or data coordinates for editors
// (time-step and opacity on the TSTF canvas).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "ui_geometry.h"

namespace tstyles::viewer {

class UiAnchors {
public:
    using Mapping = std::function<glm::vec2(glm::dvec2)>;

    // Starts a frame: anchors not published again during it are stale afterwards.
    void beginFrame() { ++frame_; }

    // A rectangle whose parameters are fractions across it.
    void publish(const std::string& name, const ScreenRect& rect);
    // A rectangle with its own mapping from parameters to pixels.
    void publish(const std::string& name, const ScreenRect& rect, Mapping mapping);

    // The centre of the anchor, or the pixel its mapping gives for `parameters`. None when no
    // widget published the name in the last frame.
    std::optional<glm::vec2> resolve(const std::string& name, const std::optional<glm::dvec2>& parameters) const;
    // The names on screen now, comma separated (for error messages).
    std::string currentNames() const;

private:
    struct Anchor {
        ScreenRect rect;
        Mapping mapping;
        std::uint64_t frame = 0;
    };
    bool isCurrent(const Anchor& anchor) const { return anchor.frame + 1 >= frame_; }

    std::map<std::string, Anchor> anchors_;
    std::uint64_t frame_ = 0;
};

}  // namespace tstyles::viewer
