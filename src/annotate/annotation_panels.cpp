// Panel placement and the tick arithmetic shared by legends, box and scale bar.
#include "annotation_panels.h"

#include <cmath>
#include <cstdio>

namespace tstyles {

PanelStack::PanelStack(Canvas& canvas, const Font& font, int pixels) : canvas_(canvas), font_(font) {
    metrics_.font = &font;
    metrics_.pixels = pixels;
    metrics_.pad = 0.6 * pixels;
    metrics_.gap = 0.5 * pixels;
    metrics_.row = std::ceil(1.4 * pixels);
    metrics_.swatch = std::round(0.9 * pixels);
    metrics_.baseline = std::round(0.5 * (metrics_.row + font.ascent(pixels) - font.descent(pixels)));
}

Rect PanelStack::place(Corner corner, double width, double height) {
    const double margin = metrics_.pad;
    const bool left = corner == Corner::TopLeft || corner == Corner::BottomLeft;
    const bool top = corner == Corner::TopLeft || corner == Corner::TopRight;
    double& used = used_[corner];
    const Rect panel{std::round(left ? margin : canvas_.width() - margin - width),
                     std::round(top ? margin + used : canvas_.height() - margin - used - height), std::ceil(width),
                     std::ceil(height)};
    used += height + 0.5 * margin;
    canvas_.fillRect(panel, {0.0f, 0.0f, 0.0f, 0.6f});
    return panel;
}

double niceStep(double span, int count) {
    if (!(span > 0.0) || count < 1) return 1.0;
    const double raw = span / count;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double factor : {1.0, 2.0, 5.0})
        if (factor * power >= raw) return factor * power;
    return 10.0 * power;
}

std::string tickLabel(double value, double step) {
    if (std::abs(value) < 1e-12 * std::max(1.0, std::abs(step))) value = 0.0;
    char text[32];
    const double magnitude = std::max(std::abs(value), std::abs(step));
    if (magnitude >= 1e6 || (magnitude > 0.0 && magnitude < 1e-4)) {
        std::snprintf(text, sizeof text, "%.3g", value);
    } else {
        const int decimals = step >= 1.0 ? 0 : std::min(6, int(std::ceil(-std::log10(step) - 1e-9)));
        std::snprintf(text, sizeof text, "%.*f", decimals, value);
    }
    return text;
}

}  // namespace tstyles
