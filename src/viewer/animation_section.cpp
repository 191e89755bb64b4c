// The side panel's Animation section (record keys, preview, export a movie) and Annotations
// section (legend, caption, box, scale bar, title), both editing the scene that is saved.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>

#include <imgui.h>

#include "key_slider.h"
#include "side_panel.h"
#include "tstyles/core/errors.h"

namespace tstyles::viewer {
namespace {

void publishLastItem(UiAnchors& anchors, const std::string& name) {
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    anchors.publish(name, ScreenRect{{min.x, min.y}, {max.x, max.y}});
}

// Changes the scene's animation, or says why not.
template <typename Change>
void changeAnimation(SidePanelState& state, Change change) {
    try {
        state.scene.animation = change();
        state.animation.message.clear();
    } catch (const InputError& error) {
        state.animation.message = error.what();
    }
}

void drawKeyList(SidePanelState& state) {
    AnimationState& animation = state.animation;
    for (std::size_t i = 0; i < animation.keys.size(); ++i) {
        ImGui::PushID(int(i));
        ImGui::Text("key at frame %d", animation.keys[i].frame);
        ImGui::SameLine();
        if (ImGui::SmallButton("show")) {
            const Animation kept = state.scene.animation;
            state.scene = animation.keys[i].scene;
            state.scene.animation = kept;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Make this key's scene the current one (to adjust and add again)");
        ImGui::SameLine();
        const bool remove = ImGui::SmallButton("delete");
        ImGui::PopID();
        if (remove) {
            changeAnimation(state, [&] { return animation.removeKey(i); });
            break;
        }
    }
}

void drawExport(SidePanelState& state, ViewerCommands& commands, UiAnchors& anchors) {
    AnimationState& animation = state.animation;
    std::array<char, 512> path{};
    std::snprintf(path.data(), path.size(), "%s", animation.moviePath.c_str());
    if (ImGui::InputText("movie", path.data(), path.size())) animation.moviePath = path.data();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip(".mp4, .webm or .gif, at the scene's image size");
    if (animation.exportProgress >= 0.0) {
        char label[32];
        std::snprintf(label, sizeof label, "frame %d of %d", int(animation.exportProgress * state.scene.animation.frames),
                      state.scene.animation.frames);
        ImGui::ProgressBar(float(animation.exportProgress), {-80.0f, 0.0f}, label);
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) commands.push_back(ViewerCommand::CancelExport);
        return;
    }
    ImGui::BeginDisabled(state.scene.animation.empty());
    if (ImGui::Button("Export movie (Ctrl+E)")) commands.push_back(ViewerCommand::ExportMovie);
    publishLastItem(anchors, "animation.export");
    ImGui::EndDisabled();
}

}  // namespace

void drawAnimationSection(SidePanelState& state, ViewerCommands& commands, UiAnchors& anchors) {
    AnimationState& animation = state.animation;
    ImGui::SetNextItemWidth(90.0f);
    ImGui::InputInt("##key frame", &animation.nextKeyFrame);
    animation.nextKeyFrame = std::max(animation.nextKeyFrame, 0);
    ImGui::SameLine();
    if (ImGui::Button("Add key at this frame (K)")) commands.push_back(ViewerCommand::AddKey);
    publishLastItem(anchors, "animation.add-key");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Records the whole scene (camera, nodes, exposure, ...) as the key at this frame; what\n"
                          "differs between keys moves in the movie. The next key goes one second later.");
    drawKeyList(state);
    if (ImGui::InputInt("frames/s", &animation.framesPerSecond)) {
        animation.framesPerSecond = std::clamp(animation.framesPerSecond, 1, 240);
        if (!state.scene.animation.empty()) state.scene.animation.framesPerSecond = animation.framesPerSecond;
    }
    if (!state.scene.animation.empty()) {
        ImGui::Checkbox("preview", &animation.previewing);
        publishLastItem(anchors, "animation.preview");
        ImGui::SameLine();
        ImGui::SliderInt("##frame", &animation.previewFrame, 0, state.scene.animation.frames - 1, "frame %d");
        animation.previewFrame = std::clamp(animation.previewFrame, 0, state.scene.animation.frames - 1);
    } else {
        animation.previewing = false;
        ImGui::TextDisabled("no keys yet: the scene has no animation");
    }
    drawExport(state, commands, anchors);
    if (!animation.message.empty()) ImGui::TextWrapped("%s", animation.message.c_str());
}

void drawAnnotationsSection(SidePanelState& state, UiAnchors& anchors) {
    Annotations& annotations = state.scene.annotations;
    ImGui::Checkbox("legend", &annotations.legend);
    publishLastItem(anchors, "annotations.legend");
    ImGui::SameLine();
    ImGui::Checkbox("caption", &annotations.caption);
    ImGui::SameLine();
    ImGui::Checkbox("box", &annotations.box);
    ImGui::SameLine();
    ImGui::Checkbox("scale bar", &annotations.scaleBar);
    std::array<char, 256> title{};
    std::snprintf(title.data(), title.size(), "%s", annotations.title.c_str());
    if (ImGui::InputText("title", title.data(), title.size())) annotations.title = title.data();
    drawKeySlider({"text size", "annotations.font_size", "%.0f px at 512", false, Interval{6.0, 40.0}},
                  annotations.fontSize);
}

}  // namespace tstyles::viewer
