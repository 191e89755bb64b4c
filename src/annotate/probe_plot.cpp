// Drawing a probe's table (probe_plot.h): the frame, the axes and their ticks shared by the line
// plot and the Hovmoeller diagram, then each one's marks.
#include "tstyles/annotate/probe_plot.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "tstyles/annotate/canvas.h"
#include "tstyles/annotate/font.h"
#include "tstyles/annotate/scene_annotations.h"

namespace tstyles {
namespace {

const glm::vec4 kBackground{0.08f, 0.08f, 0.10f, 1.0f};
const glm::vec4 kInk{0.92f, 0.92f, 0.92f, 1.0f};
const glm::vec4 kFaint{0.45f, 0.45f, 0.48f, 1.0f};
const glm::vec4 kMissing{0.30f, 0.30f, 0.32f, 1.0f};
const glm::vec4 kCurve{0.98f, 0.74f, 0.25f, 1.0f};
const glm::vec4 kMarkerRim{0.05f, 0.05f, 0.05f, 1.0f};
constexpr int kTextSize = 13;

struct ValueSpan {
    double low = 0.0;
    double high = 1.0;
    double fraction(double value) const { return high > low ? (value - low) / (high - low) : 0.5; }
};

// The present values' range, widened where they are all equal (a flat line still needs an axis).
ValueSpan spanOf(const ProbeTable& table) {
    double low = INFINITY, high = -INFINITY;
    for (const auto& column : table.values)
        for (const auto& value : column)
            if (value) {
                low = std::min(low, *value);
                high = std::max(high, *value);
            }
    if (!(low <= high)) return {0.0, 1.0};
    if (low == high) {
        const double pad = low == 0.0 ? 1.0 : 0.1 * std::abs(low);
        return {low - pad, high + pad};
    }
    return {low, high};
}

// Places the text's centre at x (its baseline at y).
void drawCentred(Canvas& canvas, const Font& font, const std::string& text, double x, double y) {
    canvas.drawText(font, text, {x - 0.5 * font.width(text, kTextSize), y}, kTextSize, kInk);
}

void drawRightAligned(Canvas& canvas, const Font& font, const std::string& text, double x, double y) {
    canvas.drawText(font, text, {x - font.width(text, kTextSize), y}, kTextSize, kInk);
}

// Ticks and labels of a value axis drawn upward along the plot's left edge (or a colour bar's right).
void drawValueTicks(Canvas& canvas, const Font& font, const Rect& plot, const ValueSpan& span, double edgeX,
                    bool labelsLeft) {
    const double step = niceStep(span.high - span.low, 5);
    for (double value = std::ceil(span.low / step) * step; value <= span.high + 1e-9 * step; value += step) {
        const double y = plot.bottom() - span.fraction(value) * plot.height;
        canvas.drawLine({edgeX - 4.0, y}, {edgeX + 4.0, y}, 1.0, kInk);
        const std::string label = tickLabel(value, step);
        const double baseline = y + 0.35 * kTextSize;
        if (labelsLeft) drawRightAligned(canvas, font, label, edgeX - 8.0, baseline);
        else canvas.drawText(font, label, {edgeX + 8.0, baseline}, kTextSize, kInk);
    }
}

// Every k-th of `count` items so that about `most` are labelled.
std::size_t labelStride(std::size_t count, std::size_t most) { return std::max<std::size_t>(1, (count + most - 1) / most); }

void drawLinePlot(Canvas& canvas, const Font& font, const ProbeTable& table, const Rect& plot) {
    const ValueSpan span = spanOf(table);
    const double first = table.times.front(), last = table.times.back();
    const auto xOf = [&](double time) {
        return last > first ? plot.x + (time - first) / (last - first) * plot.width : plot.x + 0.5 * plot.width;
    };
    const auto yOf = [&](double value) { return plot.bottom() - span.fraction(value) * plot.height; };
    const auto& values = table.values.front();
    for (std::size_t step = 0; step < values.size(); ++step) {
        const double x = xOf(table.times[step]);
        canvas.drawLine({x, plot.bottom()}, {x, plot.bottom() + 4.0}, 1.0, kInk);
        if (step % labelStride(values.size(), 8) == 0 || step + 1 == values.size())
            drawCentred(canvas, font, table.timeLabels[step], x, plot.bottom() + 8.0 + kTextSize);
        if (!values[step]) {
            canvas.fillRect({x - 2.0, plot.bottom() - 5.0, 4.0, 4.0}, kMissing);
            continue;
        }
        if (step + 1 < values.size() && values[step + 1])
            canvas.drawLine({x, yOf(*values[step])}, {xOf(table.times[step + 1]), yOf(*values[step + 1])}, 2.0, kCurve);
        if (table.timeColours.empty()) {
            canvas.fillRect({x - 3.0, yOf(*values[step]) - 3.0, 6.0, 6.0}, kCurve);
        } else {
            // The time-step's colour inside a dark rim, so that a colour near the curve's or the
            // background's still reads as a marker.
            canvas.fillRect({x - 5.0, yOf(*values[step]) - 5.0, 10.0, 10.0}, kMarkerRim);
            canvas.fillRect({x - 4.0, yOf(*values[step]) - 4.0, 8.0, 8.0}, glm::vec4(table.timeColours[step], 1.0f));
        }
    }
    drawValueTicks(canvas, font, plot, span, plot.x, true);
}

void drawColourBar(Canvas& canvas, const Font& font, const Rect& bar, const ValueSpan& span) {
    for (int row = 0; row < int(bar.height); ++row) {
        const double fraction = 1.0 - (double(row) + 0.5) / bar.height;
        canvas.fillRect({bar.x, bar.y + row, bar.width, 1.0}, glm::vec4(probeRampColour(fraction), 1.0f));
    }
    canvas.strokeRect(bar, 1.0, kFaint);
    drawValueTicks(canvas, font, bar, span, bar.right(), false);
}

void drawHovmoeller(Canvas& canvas, const Font& font, const ProbeTable& table, const Rect& plot, const Rect& bar) {
    const ValueSpan span = spanOf(table);
    const std::size_t columns = table.values.size(), rows = table.times.size();
    const double cellWidth = plot.width / double(columns), cellHeight = plot.height / double(rows);
    // Cells end on whole pixels: neighbours share no partly covered pixel, so no seam shows between them.
    const auto edge = [](double start, double cell, std::size_t index) { return std::round(start + double(index) * cell); };
    for (std::size_t column = 0; column < columns; ++column)
        for (std::size_t row = 0; row < rows; ++row) {
            const auto& value = table.values[column][row];
            const glm::vec4 colour =
                value ? glm::vec4(probeRampColour(span.fraction(*value)), 1.0f) : kMissing;
            const double x0 = edge(plot.x, cellWidth, column), x1 = edge(plot.x, cellWidth, column + 1);
            const double y0 = edge(plot.y, cellHeight, row), y1 = edge(plot.y, cellHeight, row + 1);
            canvas.fillRect({x0, y0, x1 - x0, y1 - y0}, colour);
        }
    for (std::size_t row = 0; row < rows; row += labelStride(rows, 12)) {
        const double y = plot.y + (double(row) + 0.5) * cellHeight;
        drawRightAligned(canvas, font, table.timeLabels[row], plot.x - 8.0, y + 0.35 * kTextSize);
    }
    const double length = table.distances.back();
    const double step = niceStep(length, 6);
    for (double distance = 0.0; distance <= length + 1e-9 * step; distance += step) {
        // Each column is a place: a distance sits at its column's centre.
        const double x = plot.x + (0.5 + distance / length * double(columns - 1)) * cellWidth;
        canvas.drawLine({x, plot.bottom()}, {x, plot.bottom() + 4.0}, 1.0, kInk);
        drawCentred(canvas, font, tickLabel(distance, step), x, plot.bottom() + 8.0 + kTextSize);
    }
    drawColourBar(canvas, font, bar, span);
}

}  // namespace

glm::vec3 probeRampColour(double fraction) {
    // Points along a blue-to-yellow ramp whose lightness rises steadily (as viridis does).
    static const std::array<glm::vec3, 5> kStops{glm::vec3(0.267f, 0.005f, 0.329f), glm::vec3(0.229f, 0.322f, 0.546f),
                                                 glm::vec3(0.128f, 0.567f, 0.551f), glm::vec3(0.369f, 0.789f, 0.383f),
                                                 glm::vec3(0.993f, 0.906f, 0.144f)};
    const double position = std::clamp(fraction, 0.0, 1.0) * double(kStops.size() - 1);
    const std::size_t below = std::min(std::size_t(position), kStops.size() - 2);
    return glm::mix(kStops[below], kStops[below + 1], float(position - double(below)));
}

Image drawProbePlot(const ProbeTable& table, glm::ivec2 size) {
    Image image(size.x, size.y);
    Canvas canvas(image);
    canvas.fillRect({0.0, 0.0, double(size.x), double(size.y)}, kBackground);
    const Font font = Font::openDefault();
    const bool line = table.values.size() > 1;
    const double left = line ? 90.0 : 80.0, right = line ? 110.0 : 24.0;
    const Rect plot{left, 44.0, double(size.x) - left - right, double(size.y) - 44.0 - 56.0};
    canvas.drawText(font, table.title, {left, 24.0}, kTextSize + 2, kInk);
    const std::string unit = table.unit.empty() ? "no unit" : table.unit;
    if (line) {
        drawHovmoeller(canvas, font, table, plot, {plot.right() + 24.0, plot.y, 16.0, plot.height});
        drawCentred(canvas, font, "distance along the line", plot.x + 0.5 * plot.width, double(size.y) - 12.0);
        canvas.drawText(font, unit, {plot.right() + 16.0, plot.y - 8.0}, kTextSize, kInk);
    } else {
        canvas.strokeRect(plot, 1.0, kFaint);
        drawLinePlot(canvas, font, table, plot);
        drawCentred(canvas, font, "time", plot.x + 0.5 * plot.width, double(size.y) - 12.0);
        canvas.drawText(font, unit, {8.0, plot.y - 8.0}, kTextSize, kInk);
    }
    return image;
}

}  // namespace tstyles
