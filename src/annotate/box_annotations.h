// The series' box with labelled ticks, and the scale bar, laid out in what space the panels left.
// Private to src/annotate.
#pragma once

#include "annotation_panels.h"
#include "layout_space.h"

namespace tstyles {

// A 1-2-5 length in the file's horizontal unit with its label, in the bottom-right corner: the bar
// and its label as two elements, or nothing where there is no room. The bar is a tenth to a
// quarter of the image's width.
void placeScaleBar(LayoutSpace& space, const PanelMetrics& m, const Series& series, const DisplayFrame& frame,
                   const View& view, AnnotationPlan& plan);

// Where in the space the scale bar would go at its largest (a quarter of the image wide), claiming
// nothing: the corner the picture keeps clear of.
std::optional<Rect> scaleBarCorner(const LayoutSpace& space, const PanelMetrics& m);

// The box's edges and tick marks as the plan's underlay; then each axis's title beside its tick
// labels, and the tick labels (fewer where they crowd) where they fit.
void placeBox(LayoutSpace& space, const PanelMetrics& m, const Scene& scene, const Series& series,
              const DisplayFrame& frame, const View& view, AnnotationPlan& plan);

}  // namespace tstyles
