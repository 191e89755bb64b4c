// Where the fixed panels go in the window: a menu bar on top, the side panel (dataset, time,
// compositor, camera, profile) on the left, the STF and TSTF editors along the bottom, and the
// volume filling the rest. Dear ImGui 1.86 has no docking, so the layout is computed, not dragged.
#pragma once

#include <glm/glm.hpp>

#include "ui_geometry.h"

namespace tstyles::viewer {

struct ViewerLayout {
    ScreenRect sidePanel;
    ScreenRect stfEditor;
    ScreenRect tstfEditor;
    ScreenRect volume;
};

ViewerLayout layoutViewer(glm::vec2 windowSize, float menuBarHeight);

}  // namespace tstyles::viewer
