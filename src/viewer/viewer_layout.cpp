// Panel sizes follow the window within limits that keep the panels usable and the volume large.
#include "viewer_layout.h"

#include <algorithm>
#include <cmath>

namespace tstyles::viewer {

ViewerLayout layoutViewer(glm::vec2 windowSize, float menuBarHeight, bool withProbePanel) {
    const float width = std::max(windowSize.x, 320.0f);
    const float height = std::max(windowSize.y, 240.0f);
    const float sideWidth = std::round(std::clamp(0.24f * width, 250.0f, 360.0f));
    const float editorHeight = std::round(std::clamp(0.36f * height, 180.0f, 330.0f));
    // The TSTF gets more room than the STF: it holds one section per time-step.
    const float stfWidth = std::round(0.4f * width);

    ViewerLayout layout;
    const float editorTop = height - editorHeight;
    layout.sidePanel = {{0.0f, menuBarHeight}, {sideWidth, editorTop}};
    layout.stfEditor = {{0.0f, editorTop}, {stfWidth, height}};
    layout.tstfEditor = {{stfWidth, editorTop}, {width, height}};
    layout.volume = {{sideWidth, menuBarHeight}, {width, editorTop}};
    if (withProbePanel) {
        const float probeHeight = std::round(std::clamp(0.3f * (editorTop - menuBarHeight), 140.0f, 260.0f));
        layout.probePanel = {{sideWidth, editorTop - probeHeight}, {width, editorTop}};
        layout.volume.max.y = editorTop - probeHeight;
    }
    return layout;
}

}  // namespace tstyles::viewer
