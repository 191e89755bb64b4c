// The panel on the left: the dataset (time-steps, grids, placement, value range, memory) with the
// time slider and play button; the compositor settings (TC, ray mode, step, termination, final mode,
// gradient-TSTF range, background); the camera; how to pin probes; annotations; animation.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "animation_state.h"
#include "time_control.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"
#include "ui_anchors.h"
#include "ui_geometry.h"
#include "viewer_commands.h"

namespace tstyles::viewer {

struct GpuMemory {
    std::size_t seriesBytes = 0;
    std::size_t gradientBytes = 0;  // of seriesBytes, the precomputed gradients for styles
    std::size_t frameBytes = 0;
    // What the GPU memory limits changed in how the series is stored (residencyChanges); empty: as read.
    std::vector<std::string> storageChanges;
};

struct SidePanelState {
    Scene& scene;
    const Series& series;
    const std::vector<std::string>& timeLabels;  // ViewerDocument::timeLabels
    TimeControl& time;
    GpuMemory memory;
    double defaultStep = 0.0;  // the renderer's step when the scene leaves it out
    AnimationState& animation;
};

void drawSidePanel(const ScreenRect& rect, SidePanelState& state, ViewerCommands& commands, UiAnchors& anchors);

// The compositor list's entry for the scene's own code (it cannot be typed in the viewer).
inline constexpr const char* kCustomCompositorChoice = "custom (from the scene)";
// The compositors the viewer offers: every named one, and the scene's own code when it has some
// (kept in the scene while another compositor is chosen, to choose again).
std::vector<std::string> compositorChoices(const Scene& scene);

// The sections, one file each.
void drawDatasetSection(SidePanelState& state, UiAnchors& anchors);
void drawTimeSection(SidePanelState& state, ViewerCommands& commands, UiAnchors& anchors);
void drawCompositorSection(SidePanelState& state);
// Inside the compositor section: the ray mode and its options (ray_mode_section.cpp).
void drawRayModeSection(Scene& scene, const Series& shown);
void drawCameraSection(SidePanelState& state, ViewerCommands& commands);
void drawProbesSection(SidePanelState& state);
void drawAnnotationsSection(SidePanelState& state, UiAnchors& anchors);
void drawAnimationSection(SidePanelState& state, ViewerCommands& commands, UiAnchors& anchors);

}  // namespace tstyles::viewer
