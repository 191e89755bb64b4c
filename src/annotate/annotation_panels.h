// The sizes the annotations are laid out by, and a panel before it is placed: its size and how to
// draw it once the layout has put it somewhere. Private to src/annotate.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "tstyles/annotate/canvas.h"
#include "tstyles/annotate/scene_annotations.h"

namespace tstyles {

// Sizes derived from the text size, so that everything scales with the image.
struct PanelMetrics {
    const Font* font = nullptr;
    int pixels = 13;
    double pad = 8.0;        // inside a panel, and a panel's distance from the image's edges
    double gap = 6.0;        // between a swatch and its label
    double row = 18.0;       // one line of text
    double swatch = 12.0;    // a swatch's side
    double baseline = 13.0;  // from a row's top to its baseline
    double textWidth(std::string_view text) const { return font->width(text, pixels); }
};

PanelMetrics panelMetrics(const Font& font, int pixels);

// "vertical x 680" where the display's vertical is exaggerated (DisplayFrame::verticalExaggeration
// other than 1), for the vertical axis's title and the scale bar; empty otherwise.
std::string exaggerationNote(const DisplayFrame& frame);

// A panel not placed yet. `draw` paints it all (background included) inside the rectangle it is
// given; `record` notes what the viewer picks in it (the legend's swatches) and may be empty.
struct PanelDraft {
    AnnotationKind kind = AnnotationKind::Legend;
    std::string text;  // its heading or text, for the layout
    double width = 0.0;
    double height = 0.0;
    std::function<void(Canvas&, const Rect&)> draw;
    std::function<void(const Rect&, AnnotationLayout&)> record;
};

// The dark, translucent ground under a panel's text.
void fillPanel(Canvas& canvas, const Rect& panel);

// An element placed: into the layout, with its drawing.
void addElement(AnnotationPlan& plan, AnnotationKind kind, const Rect& rect, std::string text,
                std::function<void(Canvas&)> draw);

}  // namespace tstyles
