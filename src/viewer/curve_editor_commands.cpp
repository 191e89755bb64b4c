// The editors' commands (group, ungroup, delete, nudge) and the inspector of the selected node.
#include <algorithm>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "curve_editor.h"
#include "tstyles/render/style_library.h"
#include "tstyles/scene/style_reference.h"

namespace tstyles::viewer {
namespace {

void drawGroupNote(NodeGroup group) {
    if (group > 0)
        ImGui::TextDisabled("group %d (Alt+drag moves this node alone)", group);
    else
        ImGui::TextDisabled("no group");
}

}  // namespace

bool CurveEditor::groupSelection(TransferFunction1D& curve) {
    return groupNodes(curve, selection_) > 0;
}

bool CurveEditor::ungroupSelection(TransferFunction1D& curve) {
    const TransferFunction1D before = curve;
    ungroupNodes(curve, selection_);
    return !(curve == before);
}

bool CurveEditor::deleteSelection(TransferFunction1D& curve) {
    if (selection_.empty()) return false;
    deleteNodes(curve, selection_);
    clearSelection();
    return true;
}

bool CurveEditor::nudgeSelection(TransferFunction1D& curve, int direction, const CurveAxis& axis) {
    if (selection_.empty() || drag_) return false;
    const NodeSelection moving = withWholeGroups(curve, selection_);
    const double step = axis.timeSteps ? 1.0 : 0.01 * (axis.max - axis.min);
    EditResult result = shiftNodes(curve, moving, direction * step, axis);
    if (result.curve == curve) return false;
    curve = std::move(result.curve);
    selection_ = std::move(result.nodes);
    return true;
}

void CurveEditor::drawInspector(TransferFunction1D& curve, const CurveEditorConfig& config) {
    std::erase_if(selection_, [&](const NodeRef& node) { return !isValid(curve, node); });
    if (selection_.size() == 1) {
        const NodeRef node = *selection_.begin();
        ImGui::PushID(id_.c_str());
        if (node.kind == NodeKind::Opacity)
            drawOpacityInspector(curve, config, node.index);
        else
            drawColorInspector(curve, config, node.index);
        ImGui::PopID();
        return;
    }
    if (!selection_.empty()) {
        std::set<NodeGroup> groups;
        for (const NodeRef& node : selection_)
            if (groupOf(curve, node) > 0) groups.insert(groupOf(curve, node));
        ImGui::TextDisabled("%zu nodes selected, %zu group(s). Drag one to move them%s; arrows nudge.",
                            selection_.size(), groups.size(), config.axis.timeSteps ? " by whole time-steps" : "");
        return;
    }
    ImGui::TextDisabled("(?) click, shift-click or box to select");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Click a node: select it (a grouped node selects its group)\n"
                          "Shift+click: add to / remove from the selection   Drag on empty space: box select\n"
                          "Drag a node: move the selection (groups keep their shape%s)\n"
                          "Alt+drag: move one group member alone   Double-click: add a node\n"
                          "Del: delete   Ctrl+G: group   Ctrl+Shift+G: ungroup   Left/Right: nudge\n"
                          "Right-click: menu",
                          config.axis.timeSteps ? " and move by whole time-steps" : "");
}

void CurveEditor::drawOpacityInspector(TransferFunction1D& curve, const CurveEditorConfig& config,
                                       std::size_t index) {
    OpacityNode node = curve.opacity[index];
    bool changed = false;
    ImGui::SetNextItemWidth(70.0f);
    const double speed = (config.axis.max - config.axis.min) / 400.0;
    changed |= ImGui::DragScalar(config.axis.timeSteps ? "time-step" : "at", ImGuiDataType_Double, &node.at,
                                 float(speed), &config.axis.min, &config.axis.max, "%.3f");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70.0f);
    const double zero = 0.0;
    const double one = 1.0;
    changed |= ImGui::DragScalar("opacity", ImGuiDataType_Double, &node.opacity, 0.002f, &zero, &one, "%.3f");
    ImGui::SameLine();
    drawGroupNote(node.group);
    if (changed) {
        EditResult result = placeOpacityNode(curve, index, node.at, node.opacity, config.axis);
        curve = std::move(result.curve);
        selection_ = std::move(result.nodes);
    }
}

void CurveEditor::drawColorInspector(TransferFunction1D& curve, const CurveEditorConfig& config, std::size_t index) {
    ColorNode& node = curve.color[index];
    double at = node.at;
    ImGui::SetNextItemWidth(70.0f);
    const double speed = (config.axis.max - config.axis.min) / 400.0;
    const bool moved = ImGui::DragScalar(config.axis.timeSteps ? "time-step" : "at", ImGuiDataType_Double, &at,
                                         float(speed), &config.axis.min, &config.axis.max, "%.3f");
    ImGui::SameLine();
    float color[3] = {float(node.color.r), float(node.color.g), float(node.color.b)};
    if (ImGui::ColorEdit3(node.style.empty() ? "colour" : "tint", color, ImGuiColorEditFlags_NoInputs))
        node.color = glm::clamp(glm::dvec3(color[0], color[1], color[2]), glm::dvec3(0.0), glm::dvec3(1.0));
    ImGui::SameLine();
    // A style is a built-in lit sphere or an image file; none is a flat colour.
    if (!builtInStyles_) builtInStyles_ = builtInStyleNames();
    ImGui::SetNextItemWidth(120.0f);
    if (ImGui::BeginCombo("##style", node.style.empty() ? "flat colour" : node.style.c_str())) {
        if (ImGui::Selectable("flat colour", node.style.empty())) node.style.clear();
        for (const std::string& name : *builtInStyles_)
            if (ImGui::Selectable(name.c_str(), name == node.style)) node.style = name;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    // A file name is written when the field is left, so typing it is one undo step.
    const NodeRef ref{NodeKind::Color, index};
    if (styleDraftFor_ != ref) {
        styleDraft_ = isStyleFile(node.style) ? node.style : "";
        styleDraftFor_ = ref;
    }
    ImGui::SetNextItemWidth(80.0f);
    ImGui::InputTextWithHint("##style file", "image file", &styleDraft_);
    if (ImGui::IsItemDeactivatedAfterEdit() && !styleDraft_.empty()) node.style = styleDraft_;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A lit-sphere image of your own (square PNG, ...)");
    ImGui::SameLine();
    drawGroupNote(node.group);
    if (moved) {
        EditResult result = placeColorNode(curve, index, at, config.axis);
        curve = std::move(result.curve);
        selection_ = std::move(result.nodes);
        styleDraftFor_.reset();
    }
}

}  // namespace tstyles::viewer
