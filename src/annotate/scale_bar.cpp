// The scale bar: a length at the target's distance, in the file's horizontal unit.
#include <algorithm>
#include <cmath>

#include "box_annotations.h"
#include "box_projection.h"
#include "text_box.h"

namespace tstyles {
namespace {

constexpr glm::vec4 kBarInk{1.0f, 1.0f, 1.0f, 0.95f};  // on the scale bar's dark ground
// The bar is the 1-2-5 length at or above this share of the image's width (so at most 2.5 times it).
constexpr double kShortestBar = 0.1;

double labelHeightOf(const PanelMetrics& m) { return std::round(m.pad + m.row); }
double scaleBarHeight(const PanelMetrics& m) { return labelHeightOf(m) + m.pad + 0.6 * m.pixels; }

// Pixels per display unit at the target, across the view (the projection as drawn, so a picture
// moved and shrunk beside the panels has its own scale).
double pixelsPerDisplayUnit(const View& view, glm::ivec2 size) {
    const glm::dvec3 right{view.viewMatrix[0][0], view.viewMatrix[1][0], view.viewMatrix[2][0]};
    const auto at = projectToImage(view, size, view.target);
    const auto beside = projectToImage(view, size, view.target + right);
    return at && beside ? glm::length(*beside - *at) : 0.0;
}

}  // namespace

std::optional<Rect> scaleBarCorner(const LayoutSpace& space, const PanelMetrics& m) {
    LayoutSpace trial = space;
    return trial.placeInCorner(Corner::BottomRight, 2 * m.pad + 2.5 * kShortestBar * space.imageSize().x,
                               scaleBarHeight(m));
}

void placeScaleBar(LayoutSpace& space, const PanelMetrics& m, const Series& series, const DisplayFrame& frame,
                   const View& view, AnnotationPlan& plan) {
    const glm::ivec2 size = space.imageSize();
    const double pixelsPerDataUnit = pixelsPerDisplayUnit(view, size) * frame.scale.x;
    if (!(pixelsPerDataUnit > 0.0) || !std::isfinite(pixelsPerDataUnit)) return;
    const double length = niceStep(kShortestBar * size.x / pixelsPerDataUnit, 1);
    const double barPixels = length * pixelsPerDataUnit;
    const std::string unit = series.axes[0].unit;
    const bool degrees = unit.rfind("degree", 0) == 0;
    const std::string note = exaggerationNote(frame);
    const std::string label = tickLabel(length, length) + (degrees ? "\u00b0" : unit.empty() ? "" : " " + unit) +
                              (note.empty() ? "" : " (" + note + ")");
    const Rect labelExtent = textFrom(*m.font, label, m.pixels, {0.0, 0.0}).rect;
    const double labelWidth = std::ceil(2 * m.pad + labelExtent.width);
    const double labelHeight = labelHeightOf(m);
    const auto panel = space.placeInCorner(Corner::BottomRight, std::max(2 * m.pad + barPixels, labelWidth),
                                           scaleBarHeight(m));
    if (!panel) return;
    // The label above the bar's left end, each on a ground of its own (together, one panel).
    const Rect labelPart{panel->x, panel->y, panel->width, labelHeight};
    const Rect barPart{panel->x, labelPart.bottom(), panel->width, panel->bottom() - labelPart.bottom()};
    const TextBox text = textFrom(*m.font, label, m.pixels, {labelPart.x + m.pad, panel->y + m.pad + m.baseline});
    const Rect bar{barPart.x + m.pad, barPart.y + 0.2 * m.pixels, barPixels, std::max(2.0, 0.2 * m.pixels)};
    addElement(plan, AnnotationKind::ScaleBar, barPart, label, [barPart, bar](Canvas& canvas) {
        fillPanel(canvas, barPart);
        canvas.fillRect(bar, kBarInk);
    });
    addElement(plan, AnnotationKind::ScaleBarLabel, labelPart, label,
               [labelPart, text, &font = *m.font](Canvas& canvas) {
                   fillPanel(canvas, labelPart);
                   drawTextBox(canvas, font, text, kBarInk);
               });
}

}  // namespace tstyles
