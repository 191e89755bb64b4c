// Panel sizes and the tick arithmetic shared by legends, box and scale bar.
#include "annotation_panels.h"

#include <cmath>
#include <cstdio>

namespace tstyles {

PanelMetrics panelMetrics(const Font& font, int pixels) {
    PanelMetrics metrics;
    metrics.font = &font;
    metrics.pixels = pixels;
    metrics.pad = 0.6 * pixels;
    metrics.gap = 0.5 * pixels;
    metrics.row = std::ceil(1.4 * pixels);
    metrics.swatch = std::round(0.9 * pixels);
    metrics.baseline = std::round(0.5 * (metrics.row + font.ascent(pixels) - font.descent(pixels)));
    return metrics;
}

void fillPanel(Canvas& canvas, const Rect& panel) { canvas.fillRect(panel, {0.0f, 0.0f, 0.0f, 0.6f}); }

void addElement(AnnotationPlan& plan, AnnotationKind kind, const Rect& rect, std::string text,
                std::function<void(Canvas&)> draw) {
    plan.layout.elements.push_back({kind, rect, std::move(text)});
    plan.drawElements.push_back(std::move(draw));
}

std::string exaggerationNote(const DisplayFrame& frame) {
    if (frame.verticalExaggeration == 1.0) return "";
    const double factor = frame.verticalExaggeration;
    const bool whole = factor >= 1.0 && factor < 1e9 && factor == std::round(factor);
    char text[32];
    std::snprintf(text, sizeof text, whole ? "%.0f" : "%.3g", factor);  // 9900, not 9.9e+03
    return std::string("vertical \u00d7 ") + text;
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
