// One transfer-function editor (STF, index TSTF or gradient TSTF): selecting nodes by click,
// shift-click and rubber band, moving them (a group as a whole, by whole time-steps on the index
// TSTF), adding, deleting, grouping, and an inspector for the selected node. The paper's grouping
// interaction lives here; the rules themselves are in node_editing.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "curve_canvas.h"
#include "node_editing.h"
#include "style_thumbnails.h"
#include "ui_anchors.h"

namespace tstyles::viewer {

class CurveEditor {
public:
    explicit CurveEditor(std::string id) : id_(std::move(id)) {}

    // Draws the canvas over `area` and applies the mouse to `curve`. Returns true when the user
    // clicked into it (the editor then takes the keyboard shortcuts).
    bool drawCanvas(TransferFunction1D& curve, const CurveEditorConfig& config, const ScreenRect& area,
                    UiAnchors& anchors);
    // Group / Ungroup / Delete buttons. Returns true when one was pressed.
    bool drawToolbar(TransferFunction1D& curve, const CurveEditorConfig& config, UiAnchors& anchors);
    bool drawColorMapMenu(TransferFunction1D& curve, const CurveEditorConfig& config, UiAnchors& anchors);
    // One line: the selected node's position, value, colour, style and group, or a hint.
    void drawInspector(TransferFunction1D& curve, const CurveEditorConfig& config);

    // Each returns whether the curve changed.
    bool groupSelection(TransferFunction1D& curve);
    bool ungroupSelection(TransferFunction1D& curve);
    bool deleteSelection(TransferFunction1D& curve);
    // One time-step (index TSTF) or a hundredth of the axis along it, whole groups, clipped.
    bool nudgeSelection(TransferFunction1D& curve, int direction, const CurveAxis& axis);
    void selectAll(const TransferFunction1D& curve) { selection_ = allNodes(curve); }
    void clearSelection();

    const NodeSelection& selection() const { return selection_; }
    // A node or rubber band is being dragged.
    bool dragging() const { return drag_.has_value() || band_.has_value(); }

private:
    struct NodeDrag {
        TransferFunction1D base;  // the curve when the drag began; every frame moves from here
        NodeSelection moving;
        NodeRef grabbed;
        glm::vec2 press{0.0f};
        bool moved = false;
        bool wasSelected = false;
    };
    struct RubberBand {
        glm::vec2 start{0.0f};
        NodeSelection before;  // kept when shift extends a selection
        bool singleMembers = false;
    };

    void press(const TransferFunction1D& curve, const CurveCanvas& canvas, glm::vec2 mouse);
    void dragTo(TransferFunction1D& curve, const CurveCanvas& canvas, const CurveEditorConfig& config, glm::vec2 mouse);
    void release();
    void addNodeAt(TransferFunction1D& curve, const CurveCanvas& canvas, const CurveEditorConfig& config, glm::vec2 at);
    void drawContextMenu(TransferFunction1D& curve, const CurveCanvas& canvas, const CurveEditorConfig& config);
    void drawTooltip(const TransferFunction1D& curve, const CurveCanvas& canvas, const CurveEditorConfig& config,
                     glm::vec2 mouse) const;
    void drawOpacityInspector(TransferFunction1D& curve, const CurveEditorConfig& config, std::size_t index);
    void drawColorInspector(TransferFunction1D& curve, const CurveEditorConfig& config, std::size_t index);

    std::string id_;
    NodeSelection selection_;
    std::optional<NodeDrag> drag_;
    std::optional<RubberBand> band_;
    glm::vec2 contextMenuAt_{0.0f};
    // Whether the last press turned into a drag or a box: then a quick second press at the same
    // spot starts a new gesture, it is not a double-click that adds a node.
    bool lastGestureMoved_ = false;
    // A style image path being typed; written to the node when the field is left.
    std::string styleDraft_;
    std::optional<NodeRef> styleDraftFor_;
    // The built-in style names, read from the bundled data on first use.
    std::optional<std::vector<std::string>> builtInStyles_;
    StyleThumbnails thumbnails_;
};

}  // namespace tstyles::viewer
