// Free space for the annotations, claimed rectangle by rectangle.
#include "layout_space.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tstyles {
namespace {

Rect boundingRect(const Outline& outline) {
    glm::dvec2 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    for (const glm::dvec2& point : outline) {
        low = glm::min(low, point);
        high = glm::max(high, point);
    }
    return {low.x, low.y, high.x - low.x, high.y - low.y};
}

}  // namespace

bool rectsOverlap(const Rect& a, const Rect& b) {
    return std::min(a.right(), b.right()) > std::max(a.x, b.x) && std::min(a.bottom(), b.bottom()) > std::max(a.y, b.y);
}

Outline convexHull(std::vector<glm::dvec2> points) {
    // Andrew's monotone chain.
    std::sort(points.begin(), points.end(),
              [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return points;
    const auto turn = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    Outline hull(2 * points.size());
    std::size_t count = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (count >= 2 && turn(hull[count - 2], hull[count - 1], points[i]) <= 0.0) --count;
        hull[count++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = count + 1; i-- > 0;) {
        while (count >= lower && turn(hull[count - 2], hull[count - 1], points[i]) <= 0.0) --count;
        hull[count++] = points[i];
    }
    hull.resize(count - 1);
    return hull;
}

bool rectMeetsOutline(const Rect& rect, const Outline& outline) {
    if (outline.empty()) return false;
    // Separating axes: the rectangle's two and each edge's normal. Apart along any: no overlap.
    const std::array<glm::dvec2, 4> corners{glm::dvec2{rect.x, rect.y}, glm::dvec2{rect.right(), rect.y},
                                            glm::dvec2{rect.right(), rect.bottom()}, glm::dvec2{rect.x, rect.bottom()}};
    std::vector<glm::dvec2> axes{{1.0, 0.0}, {0.0, 1.0}};
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const glm::dvec2 edge = outline[(i + 1) % outline.size()] - outline[i];
        if (edge != glm::dvec2(0.0)) axes.push_back({-edge.y, edge.x});
    }
    for (const glm::dvec2& axis : axes) {
        double rectLow = std::numeric_limits<double>::infinity(), rectHigh = -rectLow;
        double outlineLow = rectLow, outlineHigh = -rectLow;
        for (const glm::dvec2& corner : corners) {
            rectLow = std::min(rectLow, glm::dot(axis, corner));
            rectHigh = std::max(rectHigh, glm::dot(axis, corner));
        }
        for (const glm::dvec2& point : outline) {
            outlineLow = std::min(outlineLow, glm::dot(axis, point));
            outlineHigh = std::max(outlineHigh, glm::dot(axis, point));
        }
        if (rectHigh <= outlineLow || outlineHigh <= rectLow) return false;
    }
    return true;
}

LayoutSpace::LayoutSpace(glm::ivec2 imageSize, double margin) : size_(imageSize), margin_(margin) {}

bool LayoutSpace::insideImage(const Rect& rect) const {
    return rect.x >= 0.0 && rect.y >= 0.0 && rect.right() <= size_.x && rect.bottom() <= size_.y;
}

bool LayoutSpace::isFree(const Rect& rect, const std::vector<Rect>& alsoAvoid) const {
    if (!insideImage(rect)) return false;
    const auto hits = [&rect](const Rect& other) { return rectsOverlap(rect, other); };
    return std::none_of(claimed_.begin(), claimed_.end(), hits) &&
           std::none_of(alsoAvoid.begin(), alsoAvoid.end(), hits) &&
           std::none_of(kept_.begin(), kept_.end(),
                        [&rect](const Outline& outline) { return rectMeetsOutline(rect, outline); });
}

std::optional<Rect> LayoutSpace::placeInCorner(Corner corner, double width, double height) {
    const bool left = corner == Corner::TopLeft || corner == Corner::BottomLeft;
    const bool top = corner == Corner::TopLeft || corner == Corner::TopRight;
    const double gap = std::round(0.5 * margin_);
    const auto found = nextEdge_.find(corner);
    const double edge = found != nextEdge_.end() ? found->second
                        : top                    ? std::round(margin_)
                                                 : size_.y - std::round(margin_);
    Rect panel{std::round(left ? margin_ : size_.x - margin_ - std::ceil(width)), 0.0, std::ceil(width),
               std::ceil(height)};
    panel.y = top ? edge : edge - panel.height;
    const auto blockerOf = [this, &panel]() -> std::optional<Rect> {
        for (const Rect& other : claimed_)
            if (rectsOverlap(panel, other)) return other;
        for (const Outline& outline : kept_)
            if (rectMeetsOutline(panel, outline)) return boundingRect(outline);
        return std::nullopt;
    };
    while (insideImage(panel)) {
        const std::optional<Rect> blocker = blockerOf();
        if (!blocker) {
            claim(panel);
            nextEdge_[corner] = top ? panel.bottom() + gap : panel.y - gap;
            return panel;
        }
        // Inward, past what is in the way.
        panel.y = top ? std::ceil(blocker->bottom()) + gap : std::floor(blocker->y) - gap - panel.height;
    }
    return std::nullopt;
}

}  // namespace tstyles
