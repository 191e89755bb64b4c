// The side panel's word on probes: how to pin one, and how many are pinned (the probe panel under
// the picture plots them).
#include <imgui.h>

#include "side_panel.h"

namespace tstyles::viewer {

void drawProbesSection(SidePanelState& state) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("Ctrl+click the picture to pin a probe: the panel under the picture plots its values over "
                        "time.");
    ImGui::PopTextWrapPos();
    if (!state.scene.probes.empty()) {
        ImGui::Text("%zu of %zu probes pinned", state.scene.probes.size(), kMaxProbes);
        if (ImGui::SmallButton("Remove all probes")) state.scene.probes.clear();
    }
}

}  // namespace tstyles::viewer
