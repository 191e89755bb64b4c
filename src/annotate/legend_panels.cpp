// The legends as panel drafts: sized first (longer labels shortened to the widest a panel may be),
// drawn wherever the layout puts them.
#include "legend_panels.h"

#include <algorithm>
#include <cmath>

#include "text_box.h"
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
bool stfShown(const Scene& scene) { return scene.finalMode != FinalMode::Tstf; }

// What the gradient TSTF's legend measures, in the series' units (a trend per unit of time).
std::string gradientLegendTitle(const Scene& scene, const std::string& valueUnit) {
    const TemporalCompositorInfo& info = compositorInfo(scene.compositor);
    if (info.range != AutomaticRange::SignedPerTime) return withUnit(info.valueName, valueUnit);
    return withUnit(info.valueName, valueUnit.empty() ? "per unit of time" : valueUnit + " per unit of time");
}

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
void drawSwatch(Canvas& canvas, const Rect& swatch, const ColorOpacity& value, const Image* style) {
    const glm::vec3 colour(value.color);
    const float strength = 0.2f + 0.8f * float(std::clamp(value.opacity, 0.0, 1.0));
    if (style && style->width > 0) {
        // The lit sphere, tinted, as strong as the time-step is opaque (nearest texel: swatches are
        // small).
        for (int y = int(swatch.y); y < int(std::ceil(swatch.bottom())); ++y)
            for (int x = int(swatch.x); x < int(std::ceil(swatch.right())); ++x) {
                const int u = std::clamp(int((x + 0.5 - swatch.x) / swatch.width * style->width), 0, style->width - 1);
                const int v =
                    std::clamp(int((y + 0.5 - swatch.y) / swatch.height * style->height), 0, style->height - 1);
                const glm::vec4 texel = style->at(u, v);
                if (texel.a <= 0.0f) continue;
                canvas.blend(x, y, texel.a * strength, glm::vec4(colour * glm::vec3(texel) / texel.a, 1.0f));
            }
        return;
    }
    canvas.fillRect(swatch, glm::vec4(colour, strength));
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

void drawText(Canvas& canvas, const PanelMetrics& m, const std::string& text, glm::dvec2 at, const glm::vec4& ink) {
    canvas.drawText(*m.font, text, at, m.pixels, ink);
}

// The row under the time-steps of a compositor that leaves unchanged places without time colour
// (CompositorOptions::unchanged): "no change <= 0.31 degC", in the series' units; empty without one.
std::string unchangedLabel(const LegendInputs& in) {
    const auto& unchanged = in.scene.compositorOptions.unchanged;
    if (!unchanged || !compositorInfo(in.scene.compositor).takesUnchanged) return {};
    const double change = unchanged->below * (in.series.valueRange[1] - in.series.valueRange[0]);
    std::string text = "no change \u2264 " + tickLabel(change, niceStep(change, 4) / 10.0);
    if (!in.series.valueUnit.empty()) text += " " + in.series.valueUnit;
    return unchanged->opacity <= 0.0 ? text + ": not shown" : text;
}

// Its swatch: the neutral white that unchanged places show, as strong as they are opaque (an empty
// outline where they are not shown).
void drawUnchangedSwatch(Canvas& canvas, const Rect& swatch, const Scene& scene) {
    const float opacity = float(std::clamp(scene.compositorOptions.unchanged->opacity, 0.0, 1.0));
    if (opacity > 0.0f) canvas.fillRect(swatch, glm::vec4(0.85f, 0.85f, 0.85f, 0.2f + 0.8f * opacity));
    canvas.strokeRect(swatch, 1.0, kFaintText);
}

// The labels of the exposed time-steps, each shortened to `room`.
std::vector<std::string> shortenedLabels(const LegendInputs& in, double room) {
    std::vector<std::string> labels;
    for (int step = in.steps.x; step <= in.steps.y; ++step)
        labels.push_back(shortenToWidth(*in.metrics.font, in.labels[std::size_t(step)], in.metrics.pixels, room));
    return labels;
}

// One row per time-step: swatch and label, the focus marked with an outline and a bright label.
PanelDraft swatchRows(const LegendInputs& in) {
    const PanelMetrics m = in.metrics;
    const double labelRoom = in.maxWidth - 2 * m.pad - m.swatch - m.gap;
    const std::vector<std::string> labels = shortenedLabels(in, labelRoom);
    const std::string unchanged = shortenToWidth(*m.font, unchangedLabel(in), m.pixels, labelRoom);
    double labelWidth = std::max(m.textWidth("time"), m.textWidth(unchanged));
    for (const std::string& label : labels) labelWidth = std::max(labelWidth, m.textWidth(label));
    const int count = int(labels.size());
    const int rows = count + (unchanged.empty() ? 0 : 1);
    const auto swatchOfRow = [m](const Rect& panel, int i) {
        const double top = panel.y + m.pad + m.row * (i + 1);
        return Rect{panel.x + m.pad, top + 0.5 * (m.row - m.swatch), m.swatch, m.swatch};
    };
    PanelDraft draft{AnnotationKind::Legend,          "time", 2 * m.pad + m.swatch + m.gap + labelWidth,
                     2 * m.pad + m.row * (rows + 1), {},     {}};
    draft.draw = [&scene = in.scene, styles = in.styles, steps = in.steps, labels, unchanged, m, swatchOfRow,
                  focus = focusSteps(in.scene, in.steps)](Canvas& canvas, const Rect& panel) {
        fillPanel(canvas, panel);
        drawText(canvas, m, "time", {panel.x + m.pad, panel.y + m.pad + m.baseline}, kFaintText);
        for (int i = 0; i < int(labels.size()); ++i) {
            const int step = steps.x + i;
            const Rect swatch = swatchOfRow(panel, i);
            drawSwatch(canvas, swatch, scene.indexTstf.atStep(step), styleOfStep(scene, step, styles));
            const bool focused = focus[std::size_t(i)];
            if (focused)
                canvas.strokeRect({swatch.x - 2, swatch.y - 2, swatch.width + 4, swatch.height + 4}, 1.0, kFocusMark);
            drawText(canvas, m, labels[std::size_t(i)],
                     {swatch.right() + m.gap, panel.y + m.pad + m.row * (i + 1) + m.baseline},
                     focused ? kText : kFaintText);
        }
        if (unchanged.empty()) return;
        const int row = int(labels.size());
        const Rect swatch = swatchOfRow(panel, row);
        drawUnchangedSwatch(canvas, swatch, scene);
        drawText(canvas, m, unchanged, {swatch.right() + m.gap, panel.y + m.pad + m.row * (row + 1) + m.baseline},
                 kFaintText);
    };
    draft.record = [steps = in.steps, labels = in.labels, swatchOfRow](const Rect& panel, AnnotationLayout& layout) {
        for (int step = steps.x; step <= steps.y; ++step) {
            layout.stepSwatches.push_back(swatchOfRow(panel, step - steps.x));
            layout.swatchSteps.push_back(step);
            layout.swatchLabels.push_back(labels[std::size_t(step)]);
        }
    };
    return draft;
}

// Too many time-steps for rows: a strip of cells, labelled at both ends and at the focus.
PanelDraft swatchStrip(const LegendInputs& in) {
    const PanelMetrics m = in.metrics;
    const int count = in.steps.y - in.steps.x + 1;
    const double stripWidth =
        std::min(std::clamp(0.4 * in.imageSize.x, 4.0 * count, 12.0 * count), in.maxWidth - 2 * m.pad);
    const double cell = stripWidth / count;
    // The end labels share the strip's width; the focus has a row of its own.
    const std::string first =
        shortenToWidth(*m.font, in.labels[std::size_t(in.steps.x)], m.pixels, 0.5 * stripWidth - m.gap);
    const std::string last =
        shortenToWidth(*m.font, in.labels[std::size_t(in.steps.y)], m.pixels, 0.5 * stripWidth - m.gap);
    const std::vector<bool> focus = focusSteps(in.scene, in.steps);
    const auto focused = std::find(focus.begin(), focus.end(), true);
    const std::string focusText =
        focused == focus.end()
            ? std::string()
            : shortenToWidth(*m.font, "focus " + in.labels[std::size_t(in.steps.x + int(focused - focus.begin()))],
                             m.pixels, stripWidth);
    const auto cellOf = [m, cell](const Rect& panel, int i) {
        return Rect{panel.x + m.pad + i * cell, panel.y + m.pad + m.row + 0.5 * (m.row - m.swatch), cell, m.swatch};
    };
    const std::string unchanged =
        shortenToWidth(*m.font, unchangedLabel(in), m.pixels, stripWidth - m.swatch - m.gap);
    // Rows: the heading, the strip, the end labels, the focus and the unchanged places where there are.
    const int rows = 3 + (focusText.empty() ? 0 : 1) + (unchanged.empty() ? 0 : 1);
    PanelDraft draft{AnnotationKind::Legend, "time", 2 * m.pad + stripWidth, 2 * m.pad + rows * m.row, {}, {}};
    draft.draw = [&scene = in.scene, styles = in.styles, steps = in.steps, m, cellOf, focus, first, last, focusText,
                  unchanged](Canvas& canvas, const Rect& panel) {
        fillPanel(canvas, panel);
        drawText(canvas, m, "time", {panel.x + m.pad, panel.y + m.pad + m.baseline}, kFaintText);
        for (int i = 0; i < steps.y - steps.x + 1; ++i) {
            const Rect swatch = cellOf(panel, i);
            drawSwatch(canvas, swatch, scene.indexTstf.atStep(steps.x + i), styleOfStep(scene, steps.x + i, styles));
            if (focus[std::size_t(i)]) canvas.fillRect({swatch.x, swatch.y - 3, swatch.width, 2}, kFocusMark);
        }
        const double labelBaseline = panel.y + m.pad + 2 * m.row + m.baseline;
        drawText(canvas, m, first, {panel.x + m.pad, labelBaseline}, kFaintText);
        drawText(canvas, m, last, {panel.right() - m.pad - m.textWidth(last), labelBaseline}, kFaintText);
        if (!focusText.empty())
            drawText(canvas, m, focusText,
                     {panel.x + 0.5 * (panel.width - m.textWidth(focusText)), labelBaseline + m.row}, kText);
        if (unchanged.empty()) return;
        const double top = panel.y + m.pad + (focusText.empty() ? 3 : 4) * m.row;
        const Rect swatch{panel.x + m.pad, top + 0.5 * (m.row - m.swatch), m.swatch, m.swatch};
        drawUnchangedSwatch(canvas, swatch, scene);
        drawText(canvas, m, unchanged, {swatch.right() + m.gap, top + m.baseline}, kFaintText);
    };
    draft.record = [steps = in.steps, labels = in.labels, cellOf](const Rect& panel, AnnotationLayout& layout) {
        for (int step = steps.x; step <= steps.y; ++step) {
            layout.stepSwatches.push_back(cellOf(panel, step - steps.x));
            layout.swatchSteps.push_back(step);
            layout.swatchLabels.push_back(labels[std::size_t(step)]);
        }
    };
    return draft;
}

// A vertical bar of a curve's colour, shown over a checkerboard with the curve's opacity, with its
// opacity drawn as a line and ticks at both ends and the middle.
void drawCurveBar(Canvas& canvas, const PanelMetrics& m, const Rect& panel, const TransferFunction1D& curve,
                  const std::string& title, const std::vector<std::string>& tickLabels) {
    fillPanel(canvas, panel);
    drawText(canvas, m, title, {panel.x + m.pad, panel.y + m.pad + m.baseline}, kFaintText);
    const Rect bar{panel.x + m.pad, panel.y + m.pad + m.row + 0.25 * m.row, m.swatch * 1.4, 6.0 * m.row};
    const int rows = int(std::ceil(bar.height));
    std::vector<glm::dvec2> opacityLine;
    for (int row = 0; row < rows; ++row) {
        const double t = 1.0 - (row + 0.5) / bar.height;  // the top is the curve's high end
        const ColorOpacity value = curve.evaluate(std::clamp(t, 0.0, 1.0));
        const Rect slice{bar.x, bar.y + row, bar.width, std::min(1.0, bar.height - row)};
        const double half = 0.5 * bar.width;
        const bool darkLeft = (row / 4) % 2 == 0;
        canvas.fillRect({slice.x, slice.y, half, slice.height}, glm::vec4(glm::vec3(darkLeft ? 0.25f : 0.45f), 1.0f));
        canvas.fillRect({slice.x + half, slice.y, half, slice.height},
                        glm::vec4(glm::vec3(darkLeft ? 0.45f : 0.25f), 1.0f));
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
        drawText(canvas, m, tickLabels[i], {bar.right() + m.gap, y + 0.35 * m.pixels}, kText);
    }
}

PanelDraft curveBar(const LegendInputs& in, const TransferFunction1D& curve, const std::string& fullTitle,
                    const std::vector<std::string>& tickLabels) {
    const PanelMetrics m = in.metrics;
    const std::string title = shortenToWidth(*m.font, fullTitle, m.pixels, in.maxWidth - 2 * m.pad);
    double labelWidth = 0.0;
    for (const std::string& label : tickLabels) labelWidth = std::max(labelWidth, m.textWidth(label));
    const double width = std::max(2 * m.pad + m.swatch * 1.4 + m.gap + labelWidth, 2 * m.pad + m.textWidth(title));
    PanelDraft draft{AnnotationKind::Legend, title, width, 2 * m.pad + m.row + 6.0 * m.row + 0.5 * m.row, {}, {}};
    draft.draw = [&curve, m, title, tickLabels](Canvas& canvas, const Rect& panel) {
        drawCurveBar(canvas, m, panel, curve, title, tickLabels);
    };
    return draft;
}

// Labels for `count` + 1 evenly spaced values from low to high.
std::vector<std::string> evenLabels(double low, double high, int count, const std::string& prefixOfLast = {},
                                    const std::string& prefixOfFirst = {}) {
    const double step = niceStep(std::abs(high - low), 4) / 10.0;
    std::vector<std::string> labels;
    for (int i = 0; i <= count; ++i)
        labels.push_back((i == count ? prefixOfLast
                          : i == 0   ? prefixOfFirst
                                     : "") +
                         tickLabel(low + (high - low) * i / count, step));
    return labels;
}

}  // namespace

std::vector<PanelDraft> legendDrafts(const LegendInputs& in) {
    std::vector<PanelDraft> drafts;
    const Scene& scene = in.scene;
    const PanelMetrics& m = in.metrics;
    if (indexTstfShown(scene)) {
        const int rowsThatFit = int((0.55 * in.imageSize.y - 2 * m.pad) / m.row) - 1;
        drafts.push_back(in.steps.y - in.steps.x + 1 <= rowsThatFit ? swatchRows(in) : swatchStrip(in));
    }
    const double valueSpan = in.series.valueRange[1] - in.series.valueRange[0];
    // Values beyond the range take its ends' colours; a signed range has values below it too.
    if (gradientTstfShown(scene))
        drafts.push_back(
            curveBar(in, scene.gradientTstf.curve, gradientLegendTitle(scene, in.series.valueUnit),
                     evenLabels(scene.gradientTstf.rangeLow * valueSpan, scene.gradientTstf.rangeHigh * valueSpan, 2,
                                "\u2265 ", scene.gradientTstf.rangeLow < 0.0 ? "\u2264 " : "")));
    if (stfShown(scene)) {
        const std::string& name = in.series.name;
        drafts.push_back(
            curveBar(in, scene.stf.curve,
                     withUnit(name.empty() || name.size() > kLongestValueName ? "value" : name, in.series.valueUnit),
                     evenLabels(in.series.valueRange[0], in.series.valueRange[1], 2)));
    }
    return drafts;
}

}  // namespace tstyles
