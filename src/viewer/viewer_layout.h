// Where the fixed panels go in the window: a menu bar on top, the side panel (dataset, time,
// compositor, camera, annotations, animation) on the left, the STF and TSTF editors along the
// bottom, the probe panel under the picture while probes are pinned, and the volume filling the
// rest. Dear ImGui 1.86 has no docking, so the layout is computed, not dragged.
#pragma once

#include <glm/glm.hpp>

#include "ui_geometry.h"

namespace tstyles::viewer {

struct ViewerLayout {
    ScreenRect sidePanel;
    ScreenRect stfEditor;
    ScreenRect tstfEditor;
    ScreenRect volume;
    ScreenRect probePanel;  // empty without probes
};

ViewerLayout layoutViewer(glm::vec2 windowSize, float menuBarHeight, bool withProbePanel);

}  // namespace tstyles::viewer
