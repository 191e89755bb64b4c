// The volume area: mouse input on the rendered image (orbit, pan, zoom, ctrl+click to pin a probe)
// and what is drawn over it (refinement progress, frame rate, the probes' markers). The image itself is
// put there by ProgressiveFrame::present before the UI is drawn on top.
#pragma once

#include <chrono>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/scene/scene.h"
#include "ui_anchors.h"
#include "ui_geometry.h"

namespace tstyles::viewer {

// A pinned probe on the picture: a ring in its colour with its number beside it.
struct ProbeMarker {
    glm::dvec3 world{0.0};
    glm::vec3 colour{1.0f};
    int number = 1;
};

struct VolumeOverlay {
    double progress = 1.0;  // of the full-quality frame
    bool refined = true;
    int previewDivisor = 1;
    double framesPerSecond = 0.0;
    double refinementSeconds = 0.0;
    std::vector<ProbeMarker> probes;
    const char* note = nullptr;  // e.g. "showing time-step 3 alone"
    // The scene's annotations take the corners: the status texts move to the middle of the edges.
    bool annotated = false;
};

class VolumeView {
public:
    // Applies this frame's mouse input over `rect` to the camera. Returns the pixel (in frame
    // pixels from the top left) that was ctrl+clicked, if any.
    std::optional<glm::dvec2> handleInput(const ScreenRect& rect, glm::vec2 framebufferScale, Camera& camera,
                                          const Bounds& bounds, glm::ivec2 frameSize, UiAnchors& anchors);
    void drawOverlay(const ScreenRect& rect, const VolumeOverlay& overlay, const Camera& camera, const Bounds& bounds,
                     glm::ivec2 frameSize) const;

    // A camera drag is under way, or the wheel turned a moment ago: keep rendering previews.
    bool interacting(std::chrono::steady_clock::time_point now) const;

private:
    bool picking_ = false;  // the held button started as a ctrl+click: no orbit until release
    std::chrono::steady_clock::time_point lastWheel_{};
    bool dragging_ = false;
};

}  // namespace tstyles::viewer
