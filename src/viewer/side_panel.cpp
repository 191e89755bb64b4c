// The side panel's window and its collapsible sections.
#include "side_panel.h"

#include <imgui.h>

namespace tstyles::viewer {

void drawSidePanel(const ScreenRect& rect, SidePanelState& state, ViewerCommands& commands, UiAnchors& anchors) {
    ImGui::SetNextWindowPos({rect.min.x, rect.min.y});
    ImGui::SetNextWindowSize({rect.size().x, rect.size().y});
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                       ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                       ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoTitleBar;
    if (ImGui::Begin("side panel", nullptr, flags)) {
        ImGui::PushItemWidth(-110.0f);
        if (ImGui::CollapsingHeader("Dataset", ImGuiTreeNodeFlags_DefaultOpen)) drawDatasetSection(state, anchors);
        if (ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) drawTimeSection(state, commands, anchors);
        if (ImGui::CollapsingHeader("Compositor", ImGuiTreeNodeFlags_DefaultOpen)) drawCompositorSection(state);
        if (ImGui::CollapsingHeader("Camera")) drawCameraSection(state, commands);
        if (ImGui::CollapsingHeader("Annotations")) drawAnnotationsSection(state, anchors);
        if (ImGui::CollapsingHeader("Animation")) drawAnimationSection(state, commands, anchors);
        if (ImGui::CollapsingHeader("Probes", ImGuiTreeNodeFlags_DefaultOpen)) drawProbesSection(state);
        ImGui::PopItemWidth();
    }
    ImGui::End();
}

}  // namespace tstyles::viewer
