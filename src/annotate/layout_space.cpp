// Free space for the annotations, claimed rectangle by rectangle.
#include "layout_space.h"

#include <algorithm>
#include <cmath>

namespace tstyles {

bool rectsOverlap(const Rect& a, const Rect& b) {
    return std::min(a.right(), b.right()) > std::max(a.x, b.x) && std::min(a.bottom(), b.bottom()) > std::max(a.y, b.y);
}

LayoutSpace::LayoutSpace(glm::ivec2 imageSize, double margin) : size_(imageSize), margin_(margin) {}

bool LayoutSpace::insideImage(const Rect& rect) const {
    return rect.x >= 0.0 && rect.y >= 0.0 && rect.right() <= size_.x && rect.bottom() <= size_.y;
}

bool LayoutSpace::isFree(const Rect& rect, const std::vector<Rect>& alsoAvoid) const {
    if (!insideImage(rect)) return false;
    const auto hits = [&rect](const Rect& other) { return rectsOverlap(rect, other); };
    return std::none_of(claimed_.begin(), claimed_.end(), hits) &&
           std::none_of(alsoAvoid.begin(), alsoAvoid.end(), hits);
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
    while (insideImage(panel)) {
        const auto blocker = std::find_if(claimed_.begin(), claimed_.end(),
                                          [&panel](const Rect& other) { return rectsOverlap(panel, other); });
        if (blocker == claimed_.end()) {
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
