// The scale bar: a length at the target's distance, in the file's horizontal unit.
#include <algorithm>
#include <cmath>

#include "box_annotations.h"
#include "text_box.h"

namespace tstyles {
namespace {

constexpr glm::vec4 kBarInk{1.0f, 1.0f, 1.0f, 0.95f};  // on the scale bar's dark ground

}  // namespace

void placeScaleBar(LayoutSpace& space, const PanelMetrics& m, const Series& series, const DisplayFrame& frame,
                   const View& view, AnnotationPlan& plan) {
    const glm::ivec2 size = space.imageSize();
    // Pixels per display unit at the target's distance (an orthographic camera shows that height
    // too).
    const double distance = glm::length(view.target - view.eye);
    const double visibleHeight = 2.0 * distance * std::tan(glm::radians(view.fovDeg) * 0.5);
    if (!(visibleHeight > 0.0) || !(frame.scale.x > 0.0)) return;
    const double pixelsPerDataUnit = size.y / visibleHeight * frame.scale.x;
    const double length = niceStep(0.2 * size.x / pixelsPerDataUnit, 1);
    const double barPixels = length * pixelsPerDataUnit;
    const std::string unit = series.axes[0].unit;
    const bool degrees = unit.rfind("degree", 0) == 0;
    const std::string label = tickLabel(length, length) + (degrees ? "\u00b0" : unit.empty() ? "" : " " + unit);
    const Rect labelExtent = textFrom(*m.font, label, m.pixels, {0.0, 0.0}).rect;
    const double labelWidth = std::ceil(2 * m.pad + labelExtent.width);
    const double labelHeight = std::round(m.pad + m.row);
    const auto panel = space.placeInCorner(Corner::BottomRight, std::max(2 * m.pad + barPixels, labelWidth),
                                           labelHeight + m.pad + 0.6 * m.pixels);
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
