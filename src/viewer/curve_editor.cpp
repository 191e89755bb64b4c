// Mouse interaction of the transfer-function editors: press, drag, release, double-click, menu.
#include "curve_editor.h"

#include "tstyles/scene/color_map.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <imgui_stdlib.h>

namespace tstyles::viewer {
namespace {

glm::vec2 toGlm(ImVec2 point) { return {point.x, point.y}; }

}  // namespace

void CurveEditor::clearSelection() {
    selection_.clear();
    drag_.reset();
    band_.reset();
    styleDraftFor_.reset();
}

bool CurveEditor::drawCanvas(TransferFunction1D& curve, const CurveEditorConfig& config, const ScreenRect& area,
                             UiAnchors& anchors) {
    // Undo or a newly opened scene may have replaced the curve under the selection.
    std::erase_if(selection_, [&](const NodeRef& node) { return !isValid(curve, node); });

    const CurveCanvas canvas = layoutCurveCanvas(area, config);
    ImGui::SetCursorScreenPos({area.min.x, area.min.y});
    ImGui::InvisibleButton((id_ + "##canvas").c_str(), {std::max(area.size().x, 1.0f), std::max(area.size().y, 1.0f)},
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool hovered = ImGui::IsItemHovered();
    const glm::vec2 mouse = toGlm(ImGui::GetIO().MousePos);
    bool clicked = false;

    if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && !lastGestureMoved_ &&
        !nodeAt(canvas, curve, mouse)) {
        addNodeAt(curve, canvas, config, mouse);
        clicked = true;
    } else if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        press(curve, canvas, mouse);
        clicked = true;
    }
    if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (drag_ && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) dragTo(curve, canvas, config, mouse);
        if (band_) {
            NodeSelection inside = nodesInRect(canvas, curve, band_->start, mouse);
            if (!band_->singleMembers) inside = withWholeGroups(curve, inside);
            selection_ = band_->before;
            selection_.insert(inside.begin(), inside.end());
        }
    }
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && (drag_ || band_)) release();
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
        contextMenuAt_ = mouse;
        clicked = true;
    }

    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    CurveEditorConfig drawing = config;
    drawing.thumbnails = &thumbnails_;
    drawCurveCanvas(drawList, canvas, curve, drawing, selection_);
    if (band_) drawRubberBand(drawList, band_->start, mouse);
    if (hovered && !dragging()) drawTooltip(curve, canvas, config, mouse);
    drawContextMenu(curve, canvas, config);

    anchors.publish(config.anchor, canvas.plot, [canvas](glm::dvec2 atOpacity) {
        return glm::vec2(canvas.xOf(atOpacity.x), canvas.yOf(atOpacity.y));
    });
    anchors.publish(config.anchor + ".colors", canvas.colorStrip, [canvas](glm::dvec2 atFraction) {
        return glm::vec2(canvas.xOf(atFraction.x),
                         canvas.colorStrip.min.y + float(atFraction.y) * canvas.colorStrip.size().y);
    });
    return clicked;
}

void CurveEditor::press(const TransferFunction1D& curve, const CurveCanvas& canvas, glm::vec2 mouse) {
    const ImGuiIO& io = ImGui::GetIO();
    const std::optional<NodeRef> hit = nodeAt(canvas, curve, mouse);
    if (!hit) {
        band_ = RubberBand{mouse, io.KeyShift ? selection_ : NodeSelection{}, io.KeyAlt};
        if (!io.KeyShift) selection_.clear();
        return;
    }
    const bool wasSelected = selection_.contains(*hit);
    NodeSelection moving;
    if (io.KeyAlt) {
        // Alt reaches into a group: one member alone, to change its own value.
        selection_ = {*hit};
        moving = selection_;
    } else if (io.KeyShift) {
        const NodeSelection group = withWholeGroups(curve, {*hit});
        if (wasSelected) {
            for (const NodeRef& node : group) selection_.erase(node);
            return;
        }
        selection_.insert(group.begin(), group.end());
        moving = withWholeGroups(curve, selection_);
    } else {
        if (!wasSelected) selection_ = withWholeGroups(curve, {*hit});
        moving = withWholeGroups(curve, selection_);
    }
    drag_ = NodeDrag{curve, moving, *hit, mouse, false, wasSelected};
}

void CurveEditor::dragTo(TransferFunction1D& curve, const CurveCanvas& canvas, const CurveEditorConfig& config,
                         glm::vec2 mouse) {
    NodeDrag& drag = *drag_;
    const glm::vec2 delta = mouse - drag.press;
    const double shift = double(delta.x) / canvas.scale();
    EditResult result;
    if (drag.moving.size() == 1) {
        // One node follows the mouse freely (both ways for an opacity node); Ctrl snaps a node on
        // the time-step axis to whole time-steps.
        const NodeRef node = *drag.moving.begin();
        const bool snap = ImGui::GetIO().KeyCtrl && config.axis.timeSteps;
        double at = positionOf(drag.base, node) + shift;
        if (snap) at = std::round(at);
        if (node.kind == NodeKind::Opacity) {
            const double opacity = canvas.opacityOf(canvas.yOf(drag.base.opacity[node.index].opacity) + delta.y);
            result = placeOpacityNode(drag.base, node.index, at, opacity, config.axis);
        } else {
            result = placeColorNode(drag.base, node.index, at, config.axis);
        }
    } else {
        // Several nodes (a group) move along the axis only and keep their shape.
        result = shiftNodes(drag.base, drag.moving, shift, config.axis);
    }
    curve = std::move(result.curve);
    selection_ = std::move(result.nodes);
    drag.moved = true;
}

void CurveEditor::release() {
    const ImVec2 dragged = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left);
    lastGestureMoved_ = (drag_ && drag_->moved) || (band_ && (dragged.x != 0.0f || dragged.y != 0.0f));
    if (drag_ && !drag_->moved && drag_->wasSelected && !ImGui::GetIO().KeyShift && !ImGui::GetIO().KeyAlt) {
        // A plain click on part of a larger selection narrows it to that node (and its group).
        selection_ = withWholeGroups(drag_->base, {drag_->grabbed});
    }
    drag_.reset();
    band_.reset();
}

void CurveEditor::addNodeAt(TransferFunction1D& curve, const CurveCanvas& canvas, const CurveEditorConfig& config,
                            glm::vec2 at) {
    const double position = canvas.atOf(at.x);
    EditResult result;
    if (at.y >= canvas.colorStrip.min.y)
        result = addColorNode(curve, position, curve.evaluate(position).color, config.axis);
    else
        result = addOpacityNode(curve, position, canvas.opacityOf(at.y), config.axis);
    curve = std::move(result.curve);
    selection_ = result.nodes;
    band_.reset();
    drag_.reset();
}

void CurveEditor::drawContextMenu(TransferFunction1D& curve, const CurveCanvas& canvas,
                                  const CurveEditorConfig& config) {
    if (!ImGui::BeginPopupContextItem((id_ + "##menu").c_str())) return;
    if (ImGui::MenuItem("Add opacity node here")) {
        const glm::vec2 at{contextMenuAt_.x, std::min(contextMenuAt_.y, canvas.colorStrip.min.y - 1.0f)};
        addNodeAt(curve, canvas, config, at);
    }
    if (ImGui::MenuItem("Add colour node here"))
        addNodeAt(curve, canvas, config, {contextMenuAt_.x, canvas.colorStrip.center().y});
    ImGui::Separator();
    if (ImGui::MenuItem("Group", "Ctrl+G", false, selection_.size() > 1)) groupSelection(curve);
    if (ImGui::MenuItem("Ungroup", "Ctrl+Shift+G", false, !selection_.empty())) ungroupSelection(curve);
    if (ImGui::MenuItem("Delete", "Del", false, !selection_.empty())) deleteSelection(curve);
    if (ImGui::MenuItem("Select all", "Ctrl+A")) selectAll(curve);
    ImGui::EndPopup();
}

void CurveEditor::drawTooltip(const TransferFunction1D& curve, const CurveCanvas& canvas,
                              const CurveEditorConfig& config, glm::vec2 mouse) const {
    const char* axisName = config.axis.timeSteps ? "time-step" : "at";
    if (const auto node = nodeAt(canvas, curve, mouse)) {
        const std::string group = groupOf(curve, *node) > 0 ? "group " + std::to_string(groupOf(curve, *node)) : "no group";
        if (node->kind == NodeKind::Opacity) {
            const OpacityNode& n = curve.opacity[node->index];
            ImGui::SetTooltip("opacity node\n%s %.3f, opacity %.3f\n%s", axisName, n.at, n.opacity, group.c_str());
        } else {
            const ColorNode& n = curve.color[node->index];
            ImGui::SetTooltip("%s node\n%s %.3f, colour (%.2f, %.2f, %.2f)%s%s\n%s",
                              n.style.empty() ? "colour" : "style", axisName, n.at, n.color.r, n.color.g, n.color.b,
                              n.style.empty() ? "" : "\nstyle: ", n.style.c_str(), group.c_str());
        }
        return;
    }
    if (!config.stepLabels.empty() && canvas.sectionRow.contains(mouse)) {
        const int step = std::clamp(int(std::lround(canvas.atOf(mouse.x))), 0, int(config.stepLabels.size()) - 1);
        const ColorOpacity value = curve.evaluate(double(step));
        ImGui::SetTooltip("time-step %d (%s)\nopacity %.3f, colour (%.2f, %.2f, %.2f)", step,
                          config.stepLabels[std::size_t(step)].c_str(), value.opacity, value.color.r, value.color.g,
                          value.color.b);
    }
}

bool CurveEditor::drawToolbar(TransferFunction1D& curve, const CurveEditorConfig& config, UiAnchors& anchors) {
    bool pressed = false;
    auto button = [&](const char* label, const char* anchor, bool enabled) {
        ImGui::BeginDisabled(!enabled);
        const bool hit = ImGui::SmallButton(label);
        ImGui::EndDisabled();
        const ImVec2 min = ImGui::GetItemRectMin();
        const ImVec2 max = ImGui::GetItemRectMax();
        anchors.publish(id_ + "." + anchor, ScreenRect{{min.x, min.y}, {max.x, max.y}});
        ImGui::SameLine();
        pressed = pressed || hit;
        return hit;
    };
    if (button("Group", "group", selection_.size() > 1)) groupSelection(curve);
    if (button("Ungroup", "ungroup", !selection_.empty())) ungroupSelection(curve);
    if (button("Delete", "delete", !selection_.empty())) deleteSelection(curve);
    pressed = drawColorMapMenu(curve, config, anchors) || pressed;
    ImGui::NewLine();
    return pressed;
}

// One click recolours the curve with a named map (color_map.h): its colour nodes become the map's
// samples over the axis, keeping the first node's lit-sphere style so shading stays.
bool CurveEditor::drawColorMapMenu(TransferFunction1D& curve, const CurveEditorConfig& config, UiAnchors& anchors) {
    const bool open = ImGui::SmallButton("Colour map...");
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    anchors.publish(id_ + ".colormap", ScreenRect{{min.x, min.y}, {max.x, max.y}});
    if (open) ImGui::OpenPopup("colour maps");
    bool applied = false;
    if (ImGui::BeginPopup("colour maps")) {
        ImDrawList& drawList = *ImGui::GetWindowDrawList();
        for (const ColorMap& map : colorMaps()) {
            const ImVec2 at = ImGui::GetCursorScreenPos();
            if (ImGui::Selectable((map.name + "##map").c_str(), false, 0, {260.0f, 0.0f})) {
                const std::string style = curve.color.empty() ? "" : curve.color.front().style;
                curve.color = colorNodesFromMap(map, config.axis.min, config.axis.max, config.axis.timeSteps, style);
                selection_.clear();
                applied = true;
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", map.purpose.c_str());
            // A preview strip of the map beside its name.
            constexpr int kSwatches = 24;
            const float left = at.x + 110.0f, width = 150.0f, height = ImGui::GetTextLineHeight();
            for (int i = 0; i < kSwatches; ++i) {
                const glm::dvec3 colour = colorAt(map, (i + 0.5) / kSwatches);
                drawList.AddRectFilled({left + width * float(i) / kSwatches, at.y},
                                       {left + width * float(i + 1) / kSwatches, at.y + height},
                                       IM_COL32(int(colour.r * 255), int(colour.g * 255), int(colour.b * 255), 255));
            }
        }
        ImGui::EndPopup();
    }
    return applied;
}

}  // namespace tstyles::viewer
