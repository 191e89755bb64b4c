// The series' bounding box with ticks in the file's units: drawn in the image plane by projecting
// the display box through the scene's view; tick labels and axis titles placed clear of the panels
// and of each other, thinned or dropped where they do not fit.
#include <algorithm>
#include <cmath>

#include "box_annotations.h"
#include "box_projection.h"
#include "text_box.h"

namespace tstyles {
namespace {

// The box and its ticks lie on the picture itself: white over a dark background, near-black over a
// light one (Figure 4's white), so that they show on either.
glm::vec4 boxInk(const glm::dvec4& background, float alpha) {
    const double luma = 0.2126 * background.r + 0.7152 * background.g + 0.0722 * background.b;
    const float level = background.a > 0.5 && luma > 0.5 ? 0.1f : 1.0f;
    return {level, level, level, alpha};
}

std::string axisTitle(const SpatialAxis& axis, int index) {
    const std::string name = axis.name.empty() ? std::string(1, char('x' + index)) : axis.name;
    return axis.unit.empty() ? name : name + " (" + axis.unit + ")";
}

// Half the rectangle's extent along a unit direction: how far its centre must stand from a line
// across that direction for it to clear the line.
double halfExtentAlong(const Rect& rect, glm::dvec2 direction) {
    return 0.5 * (std::abs(direction.x) * rect.width + std::abs(direction.y) * rect.height);
}

glm::dvec2 centreOf(const Rect& rect) { return {rect.x + 0.5 * rect.width, rect.y + 0.5 * rect.height}; }

// One axis's ticks on its edge, with a label beside each.
struct AxisTicks {
    BoxEdge edge;
    glm::dvec2 outward{0.0};  // across the edge, away from the box
    std::vector<glm::dvec2> ticks;
    std::vector<TextBox> labels;
    std::string title;
};

bool crowded(const std::vector<TextBox>& labels, double gap) {
    for (std::size_t i = 0; i < labels.size(); ++i)
        for (std::size_t j = i + 1; j < labels.size(); ++j) {
            const Rect& a = labels[i].rect;
            if (rectsOverlap({a.x - gap, a.y - gap, a.width + 2 * gap, a.height + 2 * gap}, labels[j].rect))
                return true;
        }
    return false;
}

// The ticks along the edge at `step` in the file's units from v0 (at the edge's start) to v1.
void tickAt(const PanelMetrics& m, double v0, double v1, double step, AxisTicks& axis) {
    axis.ticks.clear();
    axis.labels.clear();
    const double low = std::min(v0, v1);
    const double high = std::max(v0, v1);
    for (double value = std::ceil(low / step - 1e-9) * step; value <= high + 1e-9 * step; value += step) {
        const glm::dvec2 at = axis.edge.start + (value - v0) / (v1 - v0) * (axis.edge.end - axis.edge.start);
        TextBox label = textCentredAt(*m.font, tickLabel(value, step), m.pixels, at);
        const double away = 0.5 * m.pixels + 0.3 * m.pixels + halfExtentAlong(label.rect, axis.outward);
        const glm::dvec2 shift = at + axis.outward * away - centreOf(label.rect);
        axis.ticks.push_back(at);
        axis.labels.push_back(moved(label, glm::ivec2(glm::round(shift))));
    }
}

std::optional<AxisTicks> ticksOnEdge(const PanelMetrics& m, glm::ivec2 size, const Series& series,
                                     const DisplayFrame& frame, const View& view, const BoxEdge& edge) {
    const int axisIndex = edge.axis;
    const Bounds bounds = series.worldBounds();
    const auto centre = projectToImage(view, size, bounds.center());
    if (!centre || glm::length(edge.end - edge.start) < 3.0 * m.pixels) return std::nullopt;
    const glm::dvec3 dataStart = frame.toWorld(boxCorner(bounds, edge.from));
    const glm::dvec3 dataEnd = frame.toWorld(boxCorner(bounds, edge.from | (1 << axisIndex)));
    int dataAxis = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(dataEnd[k] - dataStart[k]) > std::abs(dataEnd[dataAxis] - dataStart[dataAxis])) dataAxis = k;
    const double v0 = dataStart[dataAxis];
    const double v1 = dataEnd[dataAxis];
    if (!(std::abs(v1 - v0) > 0.0)) return std::nullopt;
    AxisTicks axis;
    axis.edge = edge;
    const glm::dvec2 along = glm::normalize(edge.end - edge.start);
    axis.outward = {-along.y, along.x};
    if (glm::dot(axis.outward, 0.5 * (edge.start + edge.end) - *centre) < 0.0) axis.outward = -axis.outward;
    axis.title = axisTitle(series.axes[std::size_t(axisIndex)], axisIndex);
    if (axisIndex == 1 && !exaggerationNote(frame).empty()) axis.title += ", " + exaggerationNote(frame);
    // About one tick per five text heights, at least two where a 1-2-5 step allows; then fewer
    // while their labels crowd each other.
    const double length = glm::length(edge.end - edge.start);
    int most = std::max(2, int(length / (5.0 * m.pixels)));
    for (; most < 10; ++most) {
        tickAt(m, v0, v1, niceStep(std::abs(v1 - v0), most), axis);
        if (axis.ticks.size() >= 2) break;
    }
    for (int wanted = most; wanted >= 1; --wanted) {
        tickAt(m, v0, v1, niceStep(std::abs(v1 - v0), wanted), axis);
        if (!crowded(axis.labels, 0.3 * m.pixels)) return axis;
    }
    while (axis.labels.size() > 1 && crowded(axis.labels, 0.3 * m.pixels)) {  // still: every other one
        for (std::size_t i = 1; i < axis.labels.size(); ++i) {
            axis.labels.erase(axis.labels.begin() + std::ptrdiff_t(i));
            axis.ticks.erase(axis.ticks.begin() + std::ptrdiff_t(i));
        }
    }
    return axis;
}

// The axis's ticks on the best of its edges where at least two of their labels (or all, if fewer)
// find free space; else on the edge where most do.
std::optional<AxisTicks> ticksOfAxis(const LayoutSpace& space, const PanelMetrics& m, const Series& series,
                                     const DisplayFrame& frame, const View& view, int axisIndex) {
    std::optional<AxisTicks> best;
    std::size_t bestFree = 0;
    const glm::ivec2 size = space.imageSize();
    for (const BoxEdge& edge : tickEdges(view, size, series.worldBounds(), axisIndex, 3.0 * m.pixels)) {
        auto ticks = ticksOnEdge(m, size, series, frame, view, edge);
        if (!ticks) continue;
        const auto isFree = [&space](const TextBox& label) { return space.isFree(label.rect); };
        const auto free = std::size_t(std::count_if(ticks->labels.begin(), ticks->labels.end(), isFree));
        if (free >= std::min<std::size_t>(2, ticks->labels.size())) return ticks;
        if (!best || free > bestFree) best = std::move(ticks), bestFree = free;
    }
    return best;
}

std::vector<Rect> rectsOf(const std::vector<TextBox>& labels) {
    std::vector<Rect> rects;
    for (const TextBox& label : labels) rects.push_back(label.rect);
    return rects;
}

// The same box moved the least whole pixels that put it inside the image (if it can be).
TextBox keptInside(const TextBox& box, glm::ivec2 size) {
    const Rect& r = box.rect;
    const double dx = r.x < 0.0 ? -r.x : r.right() > size.x ? size.x - r.right() : 0.0;
    const double dy = r.y < 0.0 ? -r.y : r.bottom() > size.y ? size.y - r.bottom() : 0.0;
    return moved(box, glm::ivec2(int(std::ceil(dx)), int(std::ceil(dy))));
}

// Where the axis's title may go, best first: beside the tick labels (away from the edge), or past
// an end of the edge (the upper end first for an upright edge, where a plot's unit usually is).
std::vector<TextBox> titleCandidates(const PanelMetrics& m, const AxisTicks& axis, const std::string& title) {
    const double gap = 0.4 * m.pixels;
    double band = 0.5 * m.pixels;  // the tick marks, then the labels' far sides
    for (const TextBox& label : axis.labels)
        band = std::max(band, glm::dot(centreOf(label.rect) - axis.ticks.front(), axis.outward) +
                                  halfExtentAlong(label.rect, axis.outward));
    const TextBox shape = textCentredAt(*m.font, title, m.pixels, {0.0, 0.0});
    const glm::dvec2 middle = 0.5 * (axis.edge.start + axis.edge.end);
    const glm::dvec2 along = glm::normalize(axis.edge.end - axis.edge.start);
    const auto past = [&](glm::dvec2 end, glm::dvec2 direction) {
        return textCentredAt(*m.font, title, m.pixels,
                             end + direction * (gap + halfExtentAlong(shape.rect, direction)));
    };
    const TextBox beside = textCentredAt(
        *m.font, title, m.pixels, middle + axis.outward * (band + gap + halfExtentAlong(shape.rect, axis.outward)));
    const TextBox pastEnd = past(axis.edge.end, along);
    const TextBox pastStart = past(axis.edge.start, -along);
    if (std::abs(along.y) > std::abs(along.x)) {
        const bool endIsUpper = axis.edge.end.y < axis.edge.start.y;
        return {endIsUpper ? pastEnd : pastStart, beside, endIsUpper ? pastStart : pastEnd};
    }
    const bool endIsRight = axis.edge.end.x > axis.edge.start.x;
    return {beside, endIsRight ? pastEnd : pastStart, endIsRight ? pastStart : pastEnd};
}

// The axis's title where it fits: clear of every label if it can be, else clear of its own axis's
// labels (another axis's labels give way to it); shortened to a third of the image at the last.
std::optional<TextBox> placeAxisTitle(const LayoutSpace& space, const PanelMetrics& m, const AxisTicks& axis,
                                      const std::vector<Rect>& everyLabel) {
    const std::vector<Rect> ownLabels = rectsOf(axis.labels);
    const std::string shortened = shortenToWidth(*m.font, axis.title, m.pixels, space.imageSize().x / 3.0);
    for (const std::string& title : {axis.title, shortened}) {
        if (title.empty()) continue;
        for (const std::vector<Rect>* avoid : {&everyLabel, &ownLabels})
            for (const TextBox& candidate : titleCandidates(m, axis, title))
                for (const TextBox& box : {candidate, keptInside(candidate, space.imageSize())})
                    if (space.isFree(box.rect, *avoid)) return box;
    }
    return std::nullopt;
}

void drawBoxLines(Canvas& canvas, const View& view, const Bounds& bounds, const glm::vec4& ink) {
    const glm::ivec2 size(canvas.width(), canvas.height());
    for (int from = 0; from < 8; ++from)
        for (int axis = 0; axis < 3; ++axis) {
            if (from & (1 << axis)) continue;
            const auto a = projectToImage(view, size, boxCorner(bounds, from));
            const auto b = projectToImage(view, size, boxCorner(bounds, from | (1 << axis)));
            if (a && b) canvas.drawLine(*a, *b, 1.0, ink);
        }
}

}  // namespace

void placeBox(LayoutSpace& space, const PanelMetrics& m, const Scene& scene, const Series& series,
              const DisplayFrame& frame, const View& view, AnnotationPlan& plan) {
    std::vector<AxisTicks> axes;
    for (int axis = 0; axis < 3; ++axis)
        if (auto ticks = ticksOfAxis(space, m, series, frame, view, axis)) axes.push_back(std::move(*ticks));
    const glm::vec4 lineInk = boxInk(scene.background, 0.55f);
    const glm::vec4 textInk = boxInk(scene.background, 0.95f);
    plan.drawUnderlay = [view, bounds = series.worldBounds(), axes, lineInk, textInk, m](Canvas& canvas) {
        drawBoxLines(canvas, view, bounds, lineInk);
        for (const AxisTicks& axis : axes)
            for (const glm::dvec2& at : axis.ticks)
                canvas.drawLine(at, at + axis.outward * (0.5 * m.pixels), 1.0, textInk);
    };
    // Axis titles before tick labels: where space is short, labels give way first.
    std::vector<Rect> everyLabel;
    for (const AxisTicks& axis : axes)
        for (const TextBox& label : axis.labels) everyLabel.push_back(label.rect);
    const Font& font = *m.font;
    for (const AxisTicks& axis : axes)
        if (const auto title = placeAxisTitle(space, m, axis, everyLabel)) {
            space.claim(title->rect);
            addElement(plan, AnnotationKind::AxisTitle, title->rect, title->text,
                       [box = *title, textInk, &font](Canvas& canvas) { drawTextBox(canvas, font, box, textInk); });
        }
    for (const AxisTicks& axis : axes)
        for (const TextBox& label : axis.labels) {
            if (!space.isFree(label.rect)) continue;
            space.claim(label.rect);
            addElement(plan, AnnotationKind::TickLabel, label.rect, label.text,
                       [box = label, textInk, &font](Canvas& canvas) { drawTextBox(canvas, font, box, textInk); });
        }
}

}  // namespace tstyles
