// Laying out the STF and TSTF editor windows and routing the keyboard to the last one clicked.
#include "editor_panels.h"

#include <algorithm>

#include <imgui.h>

#include "tstyles/scene/temporal_compositors.h"

namespace tstyles::viewer {
namespace {

constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse |
                                         ImGuiWindowFlags_NoBringToFrontOnFocus;

void placeWindow(const ScreenRect& rect) {
    ImGui::SetNextWindowPos({rect.min.x, rect.min.y});
    ImGui::SetNextWindowSize({rect.size().x, rect.size().y});
}

// The compositors that the view's TSTF reads: the index TSTF styles each time-step of the
// composited ones too.
std::string readersOf(bool gradientTstf) {
    std::string names;
    for (const TemporalCompositor compositor : builtInCompositors()) {
        const TemporalCompositorInfo& info = compositorInfo(compositor);
        const bool gradient = info.reads == CompositorReads::GradientTstf;
        if (gradient != gradientTstf) continue;
        names += (names.empty() ? "" : ", ") + std::string(info.name);
    }
    return names;
}

}  // namespace

CurveAxis stfAxis() { return {0.0, 1.0, false}; }

CurveAxis indexTstfAxis(const Series& series) {
    return {0.0, double(std::max<std::size_t>(series.size(), 1) - 1), true};
}

CurveAxis gradientTstfAxis() { return {0.0, 1.0, false}; }

void EditorPanels::draw(Scene& scene, const Series& series, const std::vector<std::string>& timeLabels,
                        const DensityHistogram& histogram,
                        const ViewerLayout& layout, UiAnchors& anchors) {
    drawStf(scene, histogram, layout.stfEditor, anchors);
    drawTstf(scene, series, timeLabels, layout.tstfEditor, anchors);
}

void EditorPanels::drawEditor(CurveEditor& editor, TransferFunction1D& curve, const CurveEditorConfig& config,
                              UiAnchors& anchors) {
    if (editor.drawToolbar(curve, config, anchors)) focused_ = &editor;
    const float inspectorHeight = ImGui::GetFrameHeightWithSpacing();
    const ImVec2 start = ImGui::GetCursorScreenPos();
    const ImVec2 available = ImGui::GetContentRegionAvail();
    const ScreenRect area{{start.x, start.y},
                          {start.x + available.x, start.y + std::max(available.y - inspectorHeight, 40.0f)}};
    if (editor.drawCanvas(curve, config, area, anchors)) focused_ = &editor;
    ImGui::SetCursorScreenPos({area.min.x, area.max.y + ImGui::GetStyle().ItemSpacing.y});
    editor.drawInspector(curve, config);
}

void EditorPanels::drawStf(Scene& scene, const DensityHistogram& histogram, const ScreenRect& rect,
                           UiAnchors& anchors) {
    placeWindow(rect);
    const std::string title = std::string(focused_ == &stf_ ? "> " : "") + "STF: opacity and colour over density###stf";
    if (ImGui::Begin(title.c_str(), nullptr, kPanelFlags)) {
        CurveEditorConfig config;
        config.anchor = "stf";
        config.axis = stfAxis();
        config.histogram = &histogram;
        config.axisLabel = "density";
        drawEditor(stf_, scene.stf.curve, config, anchors);
    }
    ImGui::End();
}

void EditorPanels::drawTstf(Scene& scene, const Series& series, const std::vector<std::string>& timeLabels,
                            const ScreenRect& rect, UiAnchors& anchors) {
    placeWindow(rect);
    const bool focusedHere = focused_ == &index_ || focused_ == &gradient_;
    const std::string title = std::string(focusedHere ? "> " : "") + "TSTF: temporal style transfer function###tstf";
    if (ImGui::Begin(title.c_str(), nullptr, kPanelFlags)) {
        if (followCompositor_)
            tstfView_ = compositorReads(scene) == CompositorReads::GradientTstf ? TstfView::Gradient : TstfView::Index;
        if (ImGui::RadioButton("Time-step index", tstfView_ == TstfView::Index)) {
            tstfView_ = TstfView::Index;
            followCompositor_ = false;
            focused_ = &index_;
        }
        ImGui::SameLine();
        if (ImGui::RadioButton("Gradient magnitude", tstfView_ == TstfView::Gradient)) {
            tstfView_ = TstfView::Gradient;
            followCompositor_ = false;
            focused_ = &gradient_;
        }
        ImGui::SameLine();
        ImGui::TextDisabled("(?)");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Read by %s", readersOf(tstfView_ == TstfView::Gradient).c_str());
        if (tstfView_ == TstfView::Index) {
            if (focused_ == &gradient_) focused_ = &index_;
            CurveEditorConfig config;
            config.anchor = "tstf";
            config.axis = indexTstfAxis(series);
            config.stepLabels = timeLabels;
            config.axisLabel = "time-step";
            drawEditor(index_, scene.indexTstf.curve, config, anchors);
        } else {
            if (focused_ == &index_) focused_ = &gradient_;
            CurveEditorConfig config;
            config.anchor = "gradient";
            config.axis = gradientTstfAxis();
            config.axisLabel = "value (0 and 1: the ends of its range)";
            drawEditor(gradient_, scene.gradientTstf.curve, config, anchors);
        }
    }
    ImGui::End();
}

TransferFunction1D& EditorPanels::focusedCurve(Scene& scene) const {
    if (focused_ == &stf_) return scene.stf.curve;
    if (focused_ == &gradient_) return scene.gradientTstf.curve;
    return scene.indexTstf.curve;
}

CurveAxis EditorPanels::focusedAxis(const Series& series) const {
    if (focused_ == &stf_) return stfAxis();
    if (focused_ == &gradient_) return gradientTstfAxis();
    return indexTstfAxis(series);
}

void EditorPanels::clearSelections() {
    stf_.clearSelection();
    index_.clearSelection();
    gradient_.clearSelection();
}

}  // namespace tstyles::viewer
