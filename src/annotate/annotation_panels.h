// Panels stacked inward from the image's corners, with the text metrics they are laid out by; and
// the drawings under them (box, scale bar). Private to src/annotate.
#pragma once

#include <map>
#include <string_view>

#include "tstyles/annotate/canvas.h"
#include "tstyles/annotate/scene_annotations.h"

namespace tstyles {

// Sizes derived from the text size, so that everything scales with the image.
struct PanelMetrics {
    const Font* font = nullptr;
    int pixels = 13;
    double pad = 8.0;       // inside a panel
    double gap = 6.0;       // between a swatch and its label
    double row = 18.0;      // one line of text
    double swatch = 12.0;   // a swatch's side
    double baseline = 13.0; // from a row's top to its baseline
    double textWidth(std::string_view text) const { return font->width(text, pixels); }
};

class PanelStack {
public:
    PanelStack(Canvas& canvas, const Font& font, int pixels);
    // A panel of this size in the corner, below (or above) those already there, with its background drawn.
    Rect place(Corner corner, double width, double height);
    Canvas& canvas() { return canvas_; }
    const Font& font() const { return font_; }
    const PanelMetrics& metrics() const { return metrics_; }

private:
    Canvas& canvas_;
    const Font& font_;
    PanelMetrics metrics_;
    std::map<Corner, double> used_;
};

// The series' bounding box with ticks in the file's units, and the scale bar, as the scene asks.
void drawBoxAndScaleBar(PanelStack& panels, const Scene& scene, const Series& series, const DisplayFrame& frame,
                        const View& view);

}  // namespace tstyles
