// The geometry and drawing of a transfer-function editor's canvas: an opacity plot (with the
// density histogram behind the STF, or one labelled section per time-step for the index TSTF) and
// a colour strip below it holding the colour and style nodes. No interaction here (curve_editor).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "density_histogram.h"
#include "node_editing.h"
#include "ui_geometry.h"

namespace tstyles::viewer {

// What an editor edits and how to show it.
class StyleThumbnails;

struct CurveEditorConfig {
    std::string anchor;  // anchor name for scripts: "stf", "tstf", "gradient"
    CurveAxis axis;
    // Index TSTF: the time of each time-step; one section per entry. Empty for other curves.
    std::vector<std::string> stepLabels;  // the index TSTF: each time-step's stamp (sections when non-empty)
    const DensityHistogram* histogram = nullptr;  // drawn behind the STF
    StyleThumbnails* thumbnails = nullptr;        // styled nodes drawn as their lit sphere
    std::string axisLabel;
};

inline constexpr float kNodeRadius = 5.0f;
inline constexpr float kNodeHitRadius = 8.0f;
inline constexpr float kColorNodeHalfWidth = 5.0f;

struct CurveCanvas {
    ScreenRect area;        // all of it (the interactive item)
    ScreenRect sectionRow;  // time-step labels (index TSTF), else empty
    ScreenRect plot;        // opacity
    ScreenRect colorStrip;  // colour and style nodes
    ScreenRect axisRow;     // tick labels
    double displayMin = 0.0;
    double displayMax = 1.0;
    float inset = 0.0f;  // pixels kept free at the plot's left and right ends

    float xOf(double at) const;
    double atOf(float x) const;
    float yOf(double opacity) const;
    double opacityOf(float y) const;
    glm::vec2 opacityNodePoint(const OpacityNode& node) const { return {xOf(node.at), yOf(node.opacity)}; }
    glm::vec2 colorNodePoint(const ColorNode& node) const { return {xOf(node.at), colorStrip.center().y}; }
    // Pixels per axis unit.
    double scale() const;
};

CurveCanvas layoutCurveCanvas(const ScreenRect& area, const CurveEditorConfig& config);

// The node under `mouse`, if any (opacity nodes in the plot, colour nodes in the strip).
std::optional<NodeRef> nodeAt(const CurveCanvas& canvas, const TransferFunction1D& curve, glm::vec2 mouse);
// The nodes whose markers lie in the rectangle spanned by two corners.
NodeSelection nodesInRect(const CurveCanvas& canvas, const TransferFunction1D& curve, glm::vec2 a, glm::vec2 b);

void drawCurveCanvas(ImDrawList& drawList, const CurveCanvas& canvas, const TransferFunction1D& curve,
                     const CurveEditorConfig& config, const NodeSelection& selection);
void drawRubberBand(ImDrawList& drawList, glm::vec2 a, glm::vec2 b);

}  // namespace tstyles::viewer
