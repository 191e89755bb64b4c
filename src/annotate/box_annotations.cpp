// The series' bounding box with ticks in the file's units, and a scale bar: drawn in the image
// plane by projecting the display box through the scene's view.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "annotation_panels.h"

namespace tstyles {
namespace {

constexpr glm::vec4 kTickText{1.0f, 1.0f, 1.0f, 0.95f};  // on the scale bar's dark panel

// The box and its ticks lie on the picture itself: white over a dark background, near-black over a
// light one (Figure 4's white), so that they show on either.
glm::vec4 boxInk(const glm::dvec4& background, float alpha) {
    const double luma = 0.2126 * background.r + 0.7152 * background.g + 0.0722 * background.b;
    const float level = background.a > 0.5 && luma > 0.5 ? 0.1f : 1.0f;
    return {level, level, level, alpha};
}

// Pixel position of a display-space point; none behind the eye.
std::optional<glm::dvec2> project(const View& view, glm::ivec2 size, const glm::dvec3& point) {
    const glm::dvec4 clip = view.projectionMatrix * view.viewMatrix * glm::dvec4(point, 1.0);
    if (clip.w <= 1e-9) return std::nullopt;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return glm::dvec2((ndc.x * 0.5 + 0.5) * size.x, (0.5 - ndc.y * 0.5) * size.y);
}

// The file's coordinates of a display point (the inverse of DisplayFrame::toDisplay).
glm::dvec3 toData(const DisplayFrame& frame, const glm::dvec3& display) {
    return glm::transpose(frame.rotation) * (display / frame.scale);
}

std::string axisTitle(const SpatialAxis& axis, int index) {
    const std::string name = axis.name.empty() ? std::string(1, char('x' + index)) : axis.name;
    return axis.unit.empty() ? name : name + " (" + axis.unit + ")";
}

void drawBox(PanelStack& panels, const Series& series, const DisplayFrame& frame, const View& view,
             const glm::dvec4& background) {
    const glm::vec4 lineInk = boxInk(background, 0.55f);
    const glm::vec4 textInk = boxInk(background, 0.95f);
    Canvas& canvas = panels.canvas();
    const PanelMetrics& m = panels.metrics();
    const glm::ivec2 size(canvas.width(), canvas.height());
    const Bounds bounds = series.worldBounds();
    const auto corner = [&](int bits) {
        return glm::dvec3(bits & 1 ? bounds.upper.x : bounds.lower.x, bits & 2 ? bounds.upper.y : bounds.lower.y,
                          bits & 4 ? bounds.upper.z : bounds.lower.z);
    };
    for (int from = 0; from < 8; ++from)
        for (int axis = 0; axis < 3; ++axis) {
            if (from & (1 << axis)) continue;
            const auto a = project(view, size, corner(from));
            const auto b = project(view, size, corner(from | (1 << axis)));
            if (a && b) canvas.drawLine(*a, *b, 1.0, lineInk);
        }
    const auto centre = project(view, size, bounds.center());
    if (!centre) return;
    // Ticks along one edge per axis, labelled in the file's units: of the four parallel edges, the
    // one farthest out from the box's centre on screen, leaning to the bottom (the left for the
    // vertical axis), so that ticks and labels stand outside the data rather than over it.
    for (int axis = 0; axis < 3; ++axis) {
        int chosen = -1;
        double bestScore = -1e300;
        for (int from = 0; from < 8; ++from) {
            if (from & (1 << axis)) continue;
            const auto p = project(view, size, corner(from));
            const auto q = project(view, size, corner(from | (1 << axis)));
            if (!p || !q) continue;
            const glm::dvec2 middle = 0.5 * (*p + *q);
            const glm::dvec2 offset = middle - *centre;
            // An edge whose middle is off the image would carry no visible tick: any edge on it wins.
            const bool visible = middle.x >= 0.0 && middle.y >= 0.0 && middle.x <= size.x && middle.y <= size.y;
            const double score = (visible ? 1e6 : 0.0) + glm::length(offset) + 0.5 * (axis == 1 ? -offset.x : offset.y);
            if (score > bestScore) bestScore = score, chosen = from;
        }
        if (chosen < 0) continue;
        const glm::dvec3 start = corner(chosen);
        const glm::dvec3 end = corner(chosen | (1 << axis));
        const auto a = project(view, size, start);
        const auto b = project(view, size, end);
        if (!a || !b || glm::length(*b - *a) < 3.0 * m.pixels) continue;
        const glm::dvec3 dataStart = toData(frame, start);
        const glm::dvec3 dataEnd = toData(frame, end);
        int dataAxis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(dataEnd[k] - dataStart[k]) > std::abs(dataEnd[dataAxis] - dataStart[dataAxis])) dataAxis = k;
        const double v0 = dataStart[dataAxis];
        const double v1 = dataEnd[dataAxis];
        const int wanted = std::max(2, int(glm::length(*b - *a) / (5.0 * m.pixels)));
        const double step = niceStep(std::abs(v1 - v0), wanted);
        // Ticks point away from the box's centre on screen.
        const glm::dvec2 edge = glm::normalize(*b - *a);
        glm::dvec2 outward(-edge.y, edge.x);
        if (glm::dot(outward, 0.5 * (*a + *b) - *centre) < 0.0) outward = -outward;
        const double low = std::min(v0, v1);
        const double high = std::max(v0, v1);
        for (double value = std::ceil(low / step - 1e-9) * step; value <= high + 1e-9 * step; value += step) {
            const double t = (value - v0) / (v1 - v0);
            const glm::dvec2 at = *a + t * (*b - *a);
            canvas.drawLine(at, at + outward * (0.5 * m.pixels), 1.0, textInk);
            const std::string label = tickLabel(value, step);
            const glm::dvec2 labelCentre = at + outward * (1.3 * m.pixels);
            canvas.drawText(panels.font(), label, {labelCentre.x - 0.5 * m.textWidth(label), labelCentre.y + 0.35 * m.pixels},
                            m.pixels, textInk);
        }
        const std::string title = axisTitle(series.axes[std::size_t(axis)], axis);
        // The axis title beyond the edge's end, kept inside the image.
        const glm::dvec2 titleAt = *b + edge * (0.8 * m.pixels) + outward * (2.6 * m.pixels);
        const double titleWidth = m.textWidth(title);
        const double titleLeft = std::clamp(titleAt.x - 0.5 * titleWidth, 2.0, std::max(2.0, size.x - titleWidth - 2.0));
        const double titleBaseline = std::clamp(titleAt.y + 0.35 * m.pixels, double(m.pixels), size.y - 2.0);
        canvas.drawText(panels.font(), title, {titleLeft, titleBaseline}, m.pixels, textInk);
    }
}

void drawScaleBar(PanelStack& panels, const Series& series, const DisplayFrame& frame, const View& view) {
    Canvas& canvas = panels.canvas();
    const PanelMetrics& m = panels.metrics();
    // Pixels per display unit at the target's distance (an orthographic camera shows that height too).
    const double distance = glm::length(view.target - view.eye);
    const double visibleHeight = 2.0 * distance * std::tan(glm::radians(view.fovDeg) * 0.5);
    if (!(visibleHeight > 0.0)) return;
    const double pixelsPerDataUnit = canvas.height() / visibleHeight * frame.scale.x;
    const double length = niceStep(0.2 * canvas.width() / pixelsPerDataUnit, 1);
    const double pixels = length * pixelsPerDataUnit;
    const std::string unit = series.axes[0].unit;
    const bool degrees = unit.rfind("degree", 0) == 0;
    const std::string label = tickLabel(length, length) + (degrees ? "\u00b0" : unit.empty() ? "" : " " + unit);
    const Rect panel = panels.place(Corner::BottomRight, 2 * m.pad + std::max(pixels, m.textWidth(label)),
                                    2 * m.pad + m.row + 0.6 * m.pixels);
    const double barY = panel.y + m.pad + m.row + 0.2 * m.pixels;
    canvas.fillRect({panel.x + m.pad, barY, pixels, std::max(2.0, 0.2 * m.pixels)}, kTickText);
    canvas.drawText(panels.font(), label, {panel.x + m.pad, panel.y + m.pad + m.baseline}, m.pixels, kTickText);
}

}  // namespace

void drawBoxAndScaleBar(PanelStack& panels, const Scene& scene, const Series& series, const DisplayFrame& frame,
                        const View& view) {
    if (scene.annotations.box) drawBox(panels, series, frame, view, scene.background);
    if (scene.annotations.scaleBar) drawScaleBar(panels, series, frame, view);
}

}  // namespace tstyles
