// The legends, title and caption of a scene, laid out in panels stacked from the image's corners.
#include "tstyles/annotate/scene_annotations.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "annotation_panels.h"
#include "tstyles/data/time_axis.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

constexpr glm::vec4 kText{1.0f, 1.0f, 1.0f, 1.0f};
constexpr glm::vec4 kFaintText{0.78f, 0.8f, 0.85f, 1.0f};
constexpr glm::vec4 kFocusMark{1.0f, 1.0f, 1.0f, 1.0f};
// A series name longer than this (a manifest's description) is not a legend title: "value" is.
constexpr std::size_t kLongestValueName = 16;

std::string withUnit(const std::string& what, const std::string& unit) {
    return unit.empty() ? what : what + " (" + unit + ")";
}

// The index TSTF colours the time-step a compositor picks, and each time-step of the composited
// ones (temporal average, chronovolume); the gradient TSTF colours a value.
bool indexTstfShown(const Scene& scene) {
    return scene.finalMode != FinalMode::Stf && compositorReads(scene) != CompositorReads::GradientTstf;
}
bool gradientTstfShown(const Scene& scene) {
    return scene.finalMode != FinalMode::Stf && compositorReads(scene) == CompositorReads::GradientTstf;
}

// What the gradient TSTF's legend measures, in the series' units.
std::string gradientLegendTitle(const Scene& scene, const std::string& valueUnit) {
    switch (scene.compositor) {
        case TemporalCompositor::MaxDensityChange: return withUnit("change", valueUnit);
        case TemporalCompositor::StandardDeviation: return withUnit("standard deviation", valueUnit);
        case TemporalCompositor::LinearTrend:
            return withUnit("trend", valueUnit.empty() ? "per unit of time" : valueUnit + " per unit of time");
        case TemporalCompositor::Difference: return withUnit("difference", valueUnit);
        default: return withUnit("value", valueUnit);
    }
}
bool stfShown(const Scene& scene) { return scene.finalMode != FinalMode::Tstf; }


// The focus: the most opaque time-steps of the index TSTF, where opacity varies at all.
std::vector<bool> focusSteps(const Scene& scene, glm::ivec2 steps) {
    double low = 1.0, high = 0.0;
    for (int step = steps.x; step <= steps.y; ++step) {
        const double opacity = scene.indexTstf.atStep(step).opacity;
        low = std::min(low, opacity), high = std::max(high, opacity);
    }
    std::vector<bool> focus;
    for (int step = steps.x; step <= steps.y; ++step)
        focus.push_back(high - low > 0.2 && scene.indexTstf.atStep(step).opacity >= 0.5 * (low + high));
    return focus;
}

// The time-step's colour, filled as strongly as it is opaque (a faint ghost shows as a faint fill
// inside its outline), so that the swatches read like the picture.
void drawSwatch(Canvas& canvas, const Rect& swatch, const ColorOpacity& value, const Image* style = nullptr) {
    const glm::vec3 colour(value.color);
    if (style && style->width > 0) {
        // The lit sphere, tinted, as strong as the time-step is opaque (nearest texel: swatches are small).
        const float strength = 0.2f + 0.8f * float(std::clamp(value.opacity, 0.0, 1.0));
        for (int y = int(swatch.y); y < int(std::ceil(swatch.bottom())); ++y)
            for (int x = int(swatch.x); x < int(std::ceil(swatch.right())); ++x) {
                const int u = std::clamp(int((x + 0.5 - swatch.x) / swatch.width * style->width), 0, style->width - 1);
                const int v = std::clamp(int((y + 0.5 - swatch.y) / swatch.height * style->height), 0, style->height - 1);
                const glm::vec4 texel = style->at(u, v);
                if (texel.a <= 0.0f) continue;
                canvas.blend(x, y, texel.a * strength, glm::vec4(colour * glm::vec3(texel) / texel.a, 1.0f));
            }
        return;
    }
    canvas.fillRect(swatch, glm::vec4(colour, 0.2f + 0.8f * float(std::clamp(value.opacity, 0.0, 1.0))));
    canvas.strokeRect(swatch, 1.0, glm::vec4(colour, 1.0f));
}

// The style of the index TSTF's colour node nearest to the time-step (styles blend between nodes);
// null for a flat node or without style images.
const Image* styleOfStep(const Scene& scene, int step, const StyleImages& styles) {
    if (!styles || scene.indexTstf.curve.color.empty()) return nullptr;
    const auto nearest = std::min_element(
        scene.indexTstf.curve.color.begin(), scene.indexTstf.curve.color.end(),
        [step](const ColorNode& a, const ColorNode& b) { return std::abs(a.at - step) < std::abs(b.at - step); });
    return nearest->style.empty() ? nullptr : styles(nearest->style);
}

// One row per time-step: swatch and label, the focus marked with an outline and a bright label.
void drawSwatchRows(PanelStack& panels, const Scene& scene, glm::ivec2 steps, const std::vector<std::string>& labels,
                    const StyleImages& styles, AnnotationLayout& layout) {
    const PanelMetrics& m = panels.metrics();
    const std::vector<bool> focus = focusSteps(scene, steps);
    const int count = steps.y - steps.x + 1;
    double labelWidth = m.textWidth("time");
    for (int step = steps.x; step <= steps.y; ++step) labelWidth = std::max(labelWidth, m.textWidth(labels[std::size_t(step)]));
    const Rect panel = panels.place(scene.annotations.legendCorner, 2 * m.pad + m.swatch + m.gap + labelWidth,
                                    2 * m.pad + m.row * (count + 1));
    panels.canvas().drawText(panels.font(), "time", {panel.x + m.pad, panel.y + m.pad + m.baseline}, m.pixels, kFaintText);
    for (int i = 0; i < count; ++i) {
        const int step = steps.x + i;
        const double top = panel.y + m.pad + m.row * (i + 1);
        const Rect swatch{panel.x + m.pad, top + 0.5 * (m.row - m.swatch), m.swatch, m.swatch};
        drawSwatch(panels.canvas(), swatch, scene.indexTstf.atStep(step), styleOfStep(scene, step, styles));
        if (focus[std::size_t(i)])
            panels.canvas().strokeRect({swatch.x - 2, swatch.y - 2, swatch.width + 4, swatch.height + 4}, 1.0, kFocusMark);
        panels.canvas().drawText(panels.font(), labels[std::size_t(step)], {swatch.right() + m.gap, top + m.baseline},
                                 m.pixels, focus[std::size_t(i)] ? kText : kFaintText);
        layout.stepSwatches.push_back(swatch);
        layout.swatchSteps.push_back(step);
        layout.swatchLabels.push_back(labels[std::size_t(step)]);
    }
    layout.panels.push_back(panel);
}

// Too many time-steps for rows: a strip of cells, labelled at both ends and at the focus.
void drawSwatchStrip(PanelStack& panels, const Scene& scene, glm::ivec2 steps, const std::vector<std::string>& labels,
                     const StyleImages& styles, AnnotationLayout& layout) {
    const PanelMetrics& m = panels.metrics();
    const std::vector<bool> focus = focusSteps(scene, steps);
    const int count = steps.y - steps.x + 1;
    const double stripWidth = std::clamp(0.4 * panels.canvas().width(), 4.0 * count, 12.0 * count);
    const double cell = stripWidth / count;
    const Rect panel = panels.place(scene.annotations.legendCorner, 2 * m.pad + stripWidth, 2 * m.pad + 3 * m.row);
    Canvas& canvas = panels.canvas();
    canvas.drawText(panels.font(), "time", {panel.x + m.pad, panel.y + m.pad + m.baseline}, m.pixels, kFaintText);
    const double stripTop = panel.y + m.pad + m.row + 0.5 * (m.row - m.swatch);
    for (int i = 0; i < count; ++i) {
        const Rect swatch{panel.x + m.pad + i * cell, stripTop, cell, m.swatch};
        drawSwatch(canvas, swatch, scene.indexTstf.atStep(steps.x + i), styleOfStep(scene, steps.x + i, styles));
        if (focus[std::size_t(i)]) canvas.fillRect({swatch.x, stripTop - 3, cell, 2}, kFocusMark);
        layout.stepSwatches.push_back(swatch);
        layout.swatchSteps.push_back(steps.x + i);
        layout.swatchLabels.push_back(labels[std::size_t(steps.x + i)]);
    }
    const double labelBaseline = panel.y + m.pad + 2 * m.row + m.baseline;
    const std::string& first = labels[std::size_t(steps.x)];
    const std::string& last = labels[std::size_t(steps.y)];
    canvas.drawText(panels.font(), first, {panel.x + m.pad, labelBaseline}, m.pixels, kFaintText);
    canvas.drawText(panels.font(), last, {panel.right() - m.pad - m.textWidth(last), labelBaseline}, m.pixels, kFaintText);
    const auto focused = std::find(focus.begin(), focus.end(), true);
    if (focused != focus.end()) {
        const int step = steps.x + int(focused - focus.begin());
        const std::string text = "focus " + labels[std::size_t(step)];
        canvas.drawText(panels.font(), text, {panel.x + 0.5 * (panel.width - m.textWidth(text)), labelBaseline + m.row},
                        m.pixels, kText);
    }
    layout.panels.push_back(panel);
}

// A vertical bar of a curve's colour, shown over a checkerboard with the curve's opacity, with its
// opacity drawn as a line and ticks at both ends and the middle.
void drawCurveBar(PanelStack& panels, const Corner corner, const TransferFunction1D& curve, const std::string& title,
                  const std::vector<std::string>& tickLabels, AnnotationLayout& layout) {
    const PanelMetrics& m = panels.metrics();
    double labelWidth = 0.0;
    for (const std::string& label : tickLabels) labelWidth = std::max(labelWidth, m.textWidth(label));
    const double barHeight = 6.0 * m.row;
    const double width = std::max(2 * m.pad + m.swatch * 1.4 + m.gap + labelWidth, 2 * m.pad + m.textWidth(title));
    const Rect panel = panels.place(corner, width, 2 * m.pad + m.row + barHeight + 0.5 * m.row);
    Canvas& canvas = panels.canvas();
    canvas.drawText(panels.font(), title, {panel.x + m.pad, panel.y + m.pad + m.baseline}, m.pixels, kFaintText);
    const Rect bar{panel.x + m.pad, panel.y + m.pad + m.row + 0.25 * m.row, m.swatch * 1.4, barHeight};
    const int rows = int(std::ceil(bar.height));
    std::vector<glm::dvec2> opacityLine;
    for (int row = 0; row < rows; ++row) {
        const double t = 1.0 - (row + 0.5) / bar.height;  // the top is the curve's high end
        const ColorOpacity value = curve.evaluate(std::clamp(t, 0.0, 1.0));
        const Rect slice{bar.x, bar.y + row, bar.width, std::min(1.0, bar.height - row)};
        const double half = 0.5 * bar.width;
        const bool darkLeft = (row / 4) % 2 == 0;
        canvas.fillRect({slice.x, slice.y, half, slice.height}, glm::vec4(glm::vec3(darkLeft ? 0.25f : 0.45f), 1.0f));
        canvas.fillRect({slice.x + half, slice.y, half, slice.height}, glm::vec4(glm::vec3(darkLeft ? 0.45f : 0.25f), 1.0f));
        canvas.fillRect(slice, glm::vec4(glm::vec3(value.color), float(value.opacity)));
        opacityLine.push_back({bar.x + value.opacity * bar.width, bar.y + row + 0.5});
    }
    for (std::size_t i = 1; i < opacityLine.size(); ++i)
        canvas.drawLine(opacityLine[i - 1], opacityLine[i], 1.2, {1.0f, 1.0f, 1.0f, 0.9f});
    canvas.strokeRect(bar, 1.0, {1.0f, 1.0f, 1.0f, 0.6f});
    for (std::size_t i = 0; i < tickLabels.size(); ++i) {
        const double t = tickLabels.size() > 1 ? double(i) / double(tickLabels.size() - 1) : 0.0;
        const double y = bar.bottom() - t * bar.height;
        canvas.fillRect({bar.right(), y - 0.5, 0.4 * m.gap, 1.0}, kText);
        canvas.drawText(panels.font(), tickLabels[i], {bar.right() + m.gap, y + 0.35 * m.pixels}, m.pixels, kText);
    }
    layout.panels.push_back(panel);
}

// Labels for `count` + 1 evenly spaced values from low to high.
std::vector<std::string> evenLabels(double low, double high, int count, const std::string& prefixOfLast = {},
                                    const std::string& prefixOfFirst = {}) {
    const double step = niceStep(std::abs(high - low), 4) / 10.0;
    std::vector<std::string> labels;
    for (int i = 0; i <= count; ++i)
        labels.push_back((i == count ? prefixOfLast : i == 0 ? prefixOfFirst : "") +
                         tickLabel(low + (high - low) * i / count, step));
    return labels;
}

void drawCaption(PanelStack& panels, const Scene& scene, glm::ivec2 steps, const std::vector<std::string>& labels,
                 AnnotationLayout& layout) {
    const PanelMetrics& m = panels.metrics();
    std::string text = toString(scene.compositor) + " \u00b7 ";
    const int count = steps.y - steps.x + 1;
    text += count == 1 ? "time-step " + std::to_string(steps.x) : std::to_string(count) + " time-steps";
    if (labels[std::size_t(steps.x)].rfind("time-step ", 0) != 0)
        text += ", " + labels[std::size_t(steps.x)] + (count > 1 ? " to " + labels[std::size_t(steps.y)] : "");
    const Rect panel = panels.place(Corner::BottomLeft, 2 * m.pad + m.textWidth(text), 2 * m.pad + m.row);
    panels.canvas().drawText(panels.font(), text, {panel.x + m.pad, panel.y + m.pad + m.baseline}, m.pixels, kText);
    layout.panels.push_back(panel);
}

void drawTitle(PanelStack& panels, const std::string& title, AnnotationLayout& layout) {
    const PanelMetrics& m = panels.metrics();
    const int pixels = int(std::lround(1.35 * m.pixels));
    const double width = panels.font().width(title, pixels);
    const Rect panel = panels.place(Corner::TopLeft, 2 * m.pad + width, 2 * m.pad + 1.35 * m.row);
    panels.canvas().drawText(panels.font(), title, {panel.x + m.pad, panel.y + m.pad + panels.font().ascent(pixels)},
                             pixels, kText);
    layout.panels.push_back(panel);
}

}  // namespace

int annotationPixelSize(const Scene& scene, int imageHeight) {
    return std::max(6, int(std::lround(scene.annotations.fontSize * imageHeight / 512.0)));
}

std::vector<std::string> timeStepLabels(const Series& series) {
    std::vector<double> times;
    for (const TimeStep& step : series.steps) times.push_back(step.time);
    std::vector<std::string> labels = formatTimes(times, series.time);
    if (series.time.unit != TimeUnit::None) return labels;
    // Plain numbers: the index, with the stamp where it says more than the index does.
    bool stampsAreIndices = true;
    for (std::size_t step = 0; step < times.size(); ++step) stampsAreIndices = stampsAreIndices && times[step] == double(step);
    for (std::size_t step = 0; step < labels.size(); ++step)
        labels[step] = "time-step " + std::to_string(step) + (stampsAreIndices ? "" : " (" + labels[step] + ")");
    return labels;
}

AnnotationLayout drawAnnotations(Image& image, const Scene& scene, const Series& series, const DisplayFrame& frame,
                                 const View& view, const Font& font, const StyleImages& styles) {
    AnnotationLayout layout;
    if (!scene.annotations.any() || series.size() == 0) return layout;
    Canvas canvas(image);
    PanelStack panels(canvas, font, annotationPixelSize(scene, image.height));
    const glm::ivec2 steps = scene.exposure.stepsOf(series.size());
    const std::vector<std::string> labels = timeStepLabels(series);
    // Drawn first: the box and scale bar lie under the panels.
    drawBoxAndScaleBar(panels, scene, series, frame, view);
    if (!scene.annotations.title.empty()) drawTitle(panels, scene.annotations.title, layout);
    if (scene.annotations.legend) {
        const PanelMetrics& m = panels.metrics();
        const int rowsThatFit = int((0.55 * image.height - 2 * m.pad) / m.row) - 1;
        if (indexTstfShown(scene)) {
            if (steps.y - steps.x + 1 <= rowsThatFit) drawSwatchRows(panels, scene, steps, labels, styles, layout);
            else drawSwatchStrip(panels, scene, steps, labels, styles, layout);
        }
        const double valueSpan = series.valueRange[1] - series.valueRange[0];
        // Values beyond the range take its ends' colours; a signed range has values below it too.
        if (gradientTstfShown(scene))
            drawCurveBar(panels, scene.annotations.legendCorner, scene.gradientTstf.curve,
                         gradientLegendTitle(scene, series.valueUnit),
                         evenLabels(scene.gradientTstf.rangeLow * valueSpan, scene.gradientTstf.rangeHigh * valueSpan, 2,
                                    "\u2265 ", scene.gradientTstf.rangeLow < 0.0 ? "\u2264 " : ""),
                         layout);
        if (stfShown(scene))
            drawCurveBar(panels, scene.annotations.legendCorner, scene.stf.curve,
                         withUnit(series.name.empty() || series.name.size() > kLongestValueName ? "value" : series.name,
                                  series.valueUnit),
                         evenLabels(series.valueRange[0], series.valueRange[1], 2), layout);
    }
    if (scene.annotations.caption) drawCaption(panels, scene, steps, labels, layout);
    return layout;
}

}  // namespace tstyles
