// The temporal profile of the last ctrl+click: the n densities at that point, one per time-step.
#include <cmath>
#include <limits>
#include <vector>

#include <imgui.h>

#include "side_panel.h"

namespace tstyles::viewer {

void drawProfileSection(SidePanelState& state) {
    if (!state.pick) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("Ctrl+click the volume to plot the densities over time at the first visible sample.");
        ImGui::PopTextWrapPos();
        return;
    }
    const Pick& pick = *state.pick;
    if (state.pickIsNew) ImGui::SetScrollHereY(0.0f);
    ImGui::Text("at (%.3f, %.3f, %.3f)", pick.world.x, pick.world.y, pick.world.z);
    // Outside a time-step's grid, or where it has no data, there is no density; the plot shows 0
    // there and the list says which.
    std::vector<float> values;
    for (const auto& density : pick.densities)
        values.push_back(density && !isMissing(*density) ? float(*density) : 0.0f);
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::PlotLines("##profile", values.data(), int(values.size()), 0, "density over time-steps", 0.0f, 1.0f,
                     {width, 70.0f});
    if (ImGui::TreeNode("values")) {
        for (std::size_t i = 0; i < pick.densities.size(); ++i) {
            if (pick.densities[i] && isMissing(*pick.densities[i]))
                ImGui::TextDisabled("%2zu  %-10s no data", i, state.timeLabels[i].c_str());
            else if (pick.densities[i])
                ImGui::Text("%2zu  %-10s %.4f", i, state.timeLabels[i].c_str(), *pick.densities[i]);
            else
                ImGui::TextDisabled("%2zu  %-10s outside", i, state.timeLabels[i].c_str());
        }
        ImGui::TreePop();
    }
}

}  // namespace tstyles::viewer
