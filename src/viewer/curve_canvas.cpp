// Canvas layout, hit tests and drawing for the transfer-function editors.
#include "curve_canvas.h"

#include "style_thumbnails.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>

namespace tstyles::viewer {
namespace {

constexpr float kSectionRowHeight = 16.0f;
constexpr float kColorStripHeight = 18.0f;
constexpr float kAxisRowHeight = 14.0f;
constexpr float kPlotPadding = 7.0f;  // keeps nodes at opacity 0 and 1 grabbable
constexpr float kEndInset = 8.0f;     // the same for nodes at the ends of a [0, 1] axis

constexpr ImU32 kPlotBackground = IM_COL32(28, 29, 34, 255);
constexpr ImU32 kSectionShade = IM_COL32(255, 255, 255, 10);
constexpr ImU32 kSectionLine = IM_COL32(255, 255, 255, 40);
constexpr ImU32 kHistogram = IM_COL32(120, 125, 140, 110);
constexpr ImU32 kCurveLine = IM_COL32(235, 235, 240, 255);
constexpr ImU32 kNodeFill = IM_COL32(150, 160, 185, 255);
constexpr ImU32 kSelectedFill = IM_COL32(255, 255, 255, 255);
constexpr ImU32 kNodeOutline = IM_COL32(15, 15, 20, 255);
// The paper marks grouped nodes and styles with yellow circles.
constexpr ImU32 kGroupRing = IM_COL32(255, 210, 40, 255);
constexpr ImU32 kRubberBandFill = IM_COL32(100, 150, 255, 40);
constexpr ImU32 kText = IM_COL32(200, 200, 210, 255);

ImVec2 toImVec(glm::vec2 point) { return {point.x, point.y}; }

ImU32 colorOf(const glm::dvec3& color, double alpha) {
    const glm::dvec3 clamped = glm::clamp(color, glm::dvec3(0.0), glm::dvec3(1.0));
    return IM_COL32(int(clamped.r * 255.0 + 0.5), int(clamped.g * 255.0 + 0.5), int(clamped.b * 255.0 + 0.5),
                    int(std::clamp(alpha, 0.0, 1.0) * 255.0 + 0.5));
}

double luminance(const glm::dvec3& color) { return 0.2126 * color.r + 0.7152 * color.g + 0.0722 * color.b; }

void drawSections(ImDrawList& drawList, const CurveCanvas& canvas, const TransferFunction1D& curve,
                  const CurveEditorConfig& config) {
    // Sections show their time stamps where they fit, else their numbers; with many time-steps (or a
    // narrow window) only every k-th section is labelled.
    const float sectionWidth = canvas.xOf(1.0) - canvas.xOf(0.0);
    float widestStamp = 0.0f;
    for (const std::string& stamp : config.stepLabels) widestStamp = std::max(widestStamp, ImGui::CalcTextSize(stamp.c_str()).x);
    const bool stamps = widestStamp + 6.0f <= sectionWidth;
    char widest[32];
    std::snprintf(widest, sizeof widest, "%zu", config.stepLabels.size());
    const std::size_t labelEvery =
        std::max<std::size_t>(1, std::size_t(std::ceil((ImGui::CalcTextSize(widest).x + 4.0f) / sectionWidth)));
    for (std::size_t step = 0; step < config.stepLabels.size(); ++step) {
        const double at = double(step);
        const float left = canvas.xOf(at - 0.5);
        const float right = canvas.xOf(at + 0.5);
        if (step % 2 == 1)
            drawList.AddRectFilled({left, canvas.plot.min.y}, {right, canvas.plot.max.y}, kSectionShade);
        if (step > 0) drawList.AddLine({left, canvas.sectionRow.min.y}, {left, canvas.colorStrip.max.y}, kSectionLine);
        // The section's label sits on the colour and opacity this time-step gets, as in Figure 1.
        const ColorOpacity value = curve.evaluate(at);
        drawList.AddRectFilled({left + 1.0f, canvas.sectionRow.min.y}, {right - 1.0f, canvas.sectionRow.max.y},
                               colorOf(value.color, 0.15 + 0.85 * value.opacity));
        if (step % labelEvery == 0) {
            char label[64];
            std::snprintf(label, sizeof label, "%s", stamps ? config.stepLabels[step].c_str() : std::to_string(step).c_str());
            const ImVec2 textSize = ImGui::CalcTextSize(label);
            const bool dark = luminance(value.color) * (0.15 + 0.85 * value.opacity) > 0.45;
            drawList.AddText({0.5f * (left + right - textSize.x), canvas.sectionRow.min.y + 1.0f},
                             dark ? IM_COL32(0, 0, 0, 255) : IM_COL32(255, 255, 255, 255), label);
        }
        // What the time-step actually gets: a tick at its opacity across the section.
        const float y = canvas.yOf(value.opacity);
        const float margin = 0.25f * (right - left);
        drawList.AddLine({left + margin, y}, {right - margin, y}, IM_COL32(255, 255, 255, 120), 2.0f);
    }
}

void drawHistogram(ImDrawList& drawList, const CurveCanvas& canvas, const DensityHistogram& histogram) {
    const std::size_t bins = histogram.logHeights.size();
    for (std::size_t bin = 0; bin < bins; ++bin) {
        const float left = canvas.xOf(double(bin) / double(bins));
        const float right = canvas.xOf(double(bin + 1) / double(bins));
        const float top = canvas.yOf(histogram.logHeights[bin]);
        drawList.AddRectFilled({left, top}, {std::max(right, left + 1.0f), canvas.yOf(0.0)}, kHistogram);
    }
}

// The curve's colour under its opacity, column by column, and the opacity line on top.
void drawCurve(ImDrawList& drawList, const CurveCanvas& canvas, const TransferFunction1D& curve) {
    const float bottom = canvas.yOf(0.0);
    constexpr float column = 2.0f;
    for (float x = canvas.plot.min.x; x < canvas.plot.max.x; x += column) {
        const ColorOpacity value = curve.evaluate(canvas.atOf(x + 0.5f * column));
        drawList.AddRectFilled({x, canvas.yOf(value.opacity)}, {x + column, bottom}, colorOf(value.color, 0.35));
    }
    std::vector<ImVec2> points;
    points.push_back({canvas.plot.min.x, canvas.yOf(curve.evaluate(canvas.displayMin).opacity)});
    for (const OpacityNode& node : curve.opacity) points.push_back(toImVec(canvas.opacityNodePoint(node)));
    points.push_back({canvas.plot.max.x, canvas.yOf(curve.evaluate(canvas.displayMax).opacity)});
    drawList.AddPolyline(points.data(), int(points.size()), kCurveLine, 0, 1.5f);
}

void drawGroupLabel(ImDrawList& drawList, glm::vec2 at, NodeGroup group) {
    char label[32];
    std::snprintf(label, sizeof label, "%d", group);
    drawList.AddText({at.x + 7.0f, at.y - 17.0f}, kGroupRing, label);
}

void drawOpacityNodes(ImDrawList& drawList, const CurveCanvas& canvas, const TransferFunction1D& curve,
                      const NodeSelection& selection) {
    for (std::size_t i = 0; i < curve.opacity.size(); ++i) {
        const OpacityNode& node = curve.opacity[i];
        const glm::vec2 point = canvas.opacityNodePoint(node);
        const bool selected = selection.contains({NodeKind::Opacity, i});
        drawList.AddCircleFilled(toImVec(point), kNodeRadius, selected ? kSelectedFill : kNodeFill);
        drawList.AddCircle(toImVec(point), kNodeRadius, kNodeOutline, 0, 1.5f);
        if (node.group > 0) {
            drawList.AddCircle(toImVec(point), kNodeRadius + 3.0f, kGroupRing, 0, 2.0f);
            drawGroupLabel(drawList, point, node.group);
        }
    }
}

void drawColorStrip(ImDrawList& drawList, const CurveCanvas& canvas, const TransferFunction1D& curve,
                    const NodeSelection& selection, StyleThumbnails* thumbnails) {
    const ScreenRect& strip = canvas.colorStrip;
    constexpr float column = 2.0f;
    for (float x = strip.min.x; x < strip.max.x; x += column)
        drawList.AddRectFilled({x, strip.min.y + 3.0f}, {x + column, strip.max.y - 3.0f},
                               colorOf(curve.evaluate(canvas.atOf(x + 0.5f * column)).color, 1.0));
    for (std::size_t i = 0; i < curve.color.size(); ++i) {
        const ColorNode& node = curve.color[i];
        const glm::vec2 point = canvas.colorNodePoint(node);
        const bool selected = selection.contains({NodeKind::Color, i});
        const ImU32 outline = selected ? kSelectedFill : kNodeOutline;
        if (node.style.empty()) {
            const ImVec2 a{point.x - kColorNodeHalfWidth, strip.min.y};
            const ImVec2 b{point.x + kColorNodeHalfWidth, strip.max.y};
            drawList.AddRectFilled(a, b, colorOf(node.color, 1.0));
            drawList.AddRect(a, b, outline, 0.0f, 0, selected ? 2.5f : 1.5f);
            // A notch above the strip points at the node's exact position.
            drawList.AddTriangleFilled({point.x - 4.0f, strip.min.y - 5.0f}, {point.x + 4.0f, strip.min.y - 5.0f},
                                       {point.x, strip.min.y}, outline == kNodeOutline ? kNodeFill : kSelectedFill);
        } else {
            // A styled node is its lit sphere (tinted); a plain disc with a highlight if the style
            // cannot be read.
            const float radius = kColorNodeHalfWidth + 3.0f;
            const std::optional<GLuint> texture = thumbnails ? thumbnails->textureOf(node.style) : std::nullopt;
            if (texture) {
                drawList.AddImageRounded(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(*texture)),
                                         {point.x - radius, point.y - radius}, {point.x + radius, point.y + radius},
                                         {0, 0}, {1, 1}, colorOf(node.color, 1.0), radius);
            } else {
                drawList.AddCircleFilled(toImVec(point), radius, colorOf(node.color, 1.0));
                drawList.AddCircleFilled({point.x - 2.0f, point.y - 2.0f}, 2.0f, IM_COL32(255, 255, 255, 200));
            }
            drawList.AddCircle(toImVec(point), radius, outline, 0, selected ? 2.5f : 1.5f);
        }
        if (node.group > 0) {
            drawList.AddCircle(toImVec(point), kColorNodeHalfWidth + 5.0f, kGroupRing, 0, 2.0f);
        }
    }
}

void drawAxis(ImDrawList& drawList, const CurveCanvas& canvas, const CurveEditorConfig& config) {
    const float y = canvas.axisRow.min.y;
    if (config.stepLabels.empty()) {
        for (const double at : {config.axis.min, 0.5 * (config.axis.min + config.axis.max), config.axis.max}) {
            char label[32];
            std::snprintf(label, sizeof label, "%g", at);
            const float width = ImGui::CalcTextSize(label).x;
            const float x = std::clamp(canvas.xOf(at) - 0.5f * width, canvas.area.min.x, canvas.area.max.x - width);
            drawList.AddText({x, y}, kText, label);
        }
    }
    const float width = ImGui::CalcTextSize(config.axisLabel.c_str()).x;
    const float x = config.stepLabels.empty() ? canvas.xOf(0.25 * (3.0 * config.axis.min + config.axis.max)) - 0.5f * width
                                             : canvas.area.center().x - 0.5f * width;
    drawList.AddText({x, y}, IM_COL32(150, 150, 160, 255), config.axisLabel.c_str());
}

}  // namespace

float CurveCanvas::xOf(double at) const {
    const double t = (at - displayMin) / (displayMax - displayMin);
    return plot.min.x + inset + float(t) * (plot.size().x - 2.0f * inset);
}

double CurveCanvas::atOf(float x) const {
    const double t = double(x - plot.min.x - inset) / double(plot.size().x - 2.0f * inset);
    return displayMin + t * (displayMax - displayMin);
}

float CurveCanvas::yOf(double opacity) const {
    return plot.max.y - kPlotPadding - float(opacity) * (plot.size().y - 2.0f * kPlotPadding);
}

double CurveCanvas::opacityOf(float y) const {
    return double(plot.max.y - kPlotPadding - y) / double(plot.size().y - 2.0f * kPlotPadding);
}

double CurveCanvas::scale() const {
    return double(plot.size().x - 2.0f * inset) / (displayMax - displayMin);
}

CurveCanvas layoutCurveCanvas(const ScreenRect& area, const CurveEditorConfig& config) {
    CurveCanvas canvas;
    canvas.area = area;
    const bool sections = !config.stepLabels.empty();
    float top = area.min.y;
    if (sections) {
        canvas.sectionRow = {{area.min.x, top}, {area.max.x, top + kSectionRowHeight}};
        top += kSectionRowHeight;
    }
    const float axisTop = area.max.y - kAxisRowHeight;
    const float stripTop = axisTop - kColorStripHeight;
    canvas.plot = {{area.min.x, top}, {area.max.x, std::max(stripTop, top + 2.0f * kPlotPadding + 1.0f)}};
    canvas.colorStrip = {{area.min.x, stripTop}, {area.max.x, axisTop}};
    canvas.axisRow = {{area.min.x, axisTop}, {area.max.x, area.max.y}};
    if (sections) {
        // Each time-step owns the section [i - 0.5, i + 0.5], so nodes on whole steps sit mid-section.
        canvas.displayMin = -0.5;
        canvas.displayMax = double(config.stepLabels.size()) - 0.5;
    } else {
        canvas.displayMin = config.axis.min;
        canvas.displayMax = config.axis.max > config.axis.min ? config.axis.max : config.axis.min + 1.0;
        canvas.inset = kEndInset;
    }
    return canvas;
}

std::optional<NodeRef> nodeAt(const CurveCanvas& canvas, const TransferFunction1D& curve, glm::vec2 mouse) {
    std::optional<NodeRef> best;
    float bestDistance = kNodeHitRadius;
    if (mouse.y < canvas.colorStrip.min.y) {
        for (std::size_t i = 0; i < curve.opacity.size(); ++i) {
            const float distance = glm::distance(canvas.opacityNodePoint(curve.opacity[i]), mouse);
            // <= so that of two nodes on one spot the later (the one drawn on top) wins.
            if (distance <= bestDistance) {
                bestDistance = distance;
                best = NodeRef{NodeKind::Opacity, i};
            }
        }
    } else if (mouse.y < canvas.colorStrip.max.y) {
        for (std::size_t i = 0; i < curve.color.size(); ++i) {
            const float distance = std::abs(canvas.xOf(curve.color[i].at) - mouse.x);
            if (distance <= bestDistance) {
                bestDistance = distance;
                best = NodeRef{NodeKind::Color, i};
            }
        }
    }
    return best;
}

NodeSelection nodesInRect(const CurveCanvas& canvas, const TransferFunction1D& curve, glm::vec2 a, glm::vec2 b) {
    const ScreenRect rect{glm::min(a, b), glm::max(a, b)};
    auto inside = [&](glm::vec2 point) {
        return point.x >= rect.min.x && point.x <= rect.max.x && point.y >= rect.min.y && point.y <= rect.max.y;
    };
    NodeSelection nodes;
    for (std::size_t i = 0; i < curve.opacity.size(); ++i)
        if (inside(canvas.opacityNodePoint(curve.opacity[i]))) nodes.insert({NodeKind::Opacity, i});
    for (std::size_t i = 0; i < curve.color.size(); ++i)
        if (inside(canvas.colorNodePoint(curve.color[i]))) nodes.insert({NodeKind::Color, i});
    return nodes;
}

void drawCurveCanvas(ImDrawList& drawList, const CurveCanvas& canvas, const TransferFunction1D& curve,
                     const CurveEditorConfig& config, const NodeSelection& selection) {
    drawList.PushClipRect(toImVec(canvas.area.min), toImVec(canvas.area.max), true);
    drawList.AddRectFilled(toImVec(canvas.plot.min), toImVec(canvas.plot.max), kPlotBackground);
    if (config.histogram != nullptr) drawHistogram(drawList, canvas, *config.histogram);
    drawCurve(drawList, canvas, curve);
    if (!config.stepLabels.empty()) drawSections(drawList, canvas, curve, config);
    drawColorStrip(drawList, canvas, curve, selection, config.thumbnails);
    drawOpacityNodes(drawList, canvas, curve, selection);
    drawAxis(drawList, canvas, config);
    drawList.PopClipRect();
}

void drawRubberBand(ImDrawList& drawList, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 low = glm::min(a, b);
    const glm::vec2 high = glm::max(a, b);
    drawList.AddRectFilled(toImVec(low), toImVec(high), kRubberBandFill);
    drawList.AddRect(toImVec(low), toImVec(high), IM_COL32(120, 170, 255, 200));
}

}  // namespace tstyles::viewer
