// The picture moved into the room the panels leave.
#include "picture_room.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "box_projection.h"

namespace tstyles {
namespace {

Rect inflated(const Rect& rect, double by) {
    return {rect.x - by, rect.y - by, rect.width + 2.0 * by, rect.height + 2.0 * by};
}

}  // namespace

Rect PictureMove::apply(const Rect& rect) const {
    const glm::dvec2 corner = to + scale * (glm::dvec2(rect.x, rect.y) - from);
    return {corner.x, corner.y, scale * rect.width, scale * rect.height};
}

std::optional<Outline> outlineOnImage(const View& view, glm::ivec2 imageSize, const Bounds& bounds) {
    std::vector<glm::dvec2> corners;
    for (int bits = 0; bits < 8; ++bits) {
        const auto at = projectToImage(view, imageSize, boxCorner(bounds, bits));
        if (!at || !std::isfinite(at->x) || !std::isfinite(at->y)) return std::nullopt;
        corners.push_back(*at);
    }
    return convexHull(std::move(corners));
}

std::optional<Rect> footprintOnImage(const View& view, glm::ivec2 imageSize, const Bounds& bounds) {
    const auto outline = outlineOnImage(view, imageSize, bounds);
    if (!outline) return std::nullopt;
    glm::dvec2 lower(std::numeric_limits<double>::infinity());
    glm::dvec2 upper(-std::numeric_limits<double>::infinity());
    for (const glm::dvec2& point : *outline) {
        lower = glm::min(lower, point);
        upper = glm::max(upper, point);
    }
    if (!(upper.x > 0.0 && upper.y > 0.0 && lower.x < imageSize.x && lower.y < imageSize.y)) return std::nullopt;
    return Rect{lower.x, lower.y, upper.x - lower.x, upper.y - lower.y};
}

double shareKept(const Rect& footprint, const PictureMove& move, glm::ivec2 imageSize) {
    // The footprint's part on the image before the move, against the whole footprint after it.
    const double shownWidth = std::min(footprint.right(), double(imageSize.x)) - std::max(footprint.x, 0.0);
    const double shownHeight = std::min(footprint.bottom(), double(imageSize.y)) - std::max(footprint.y, 0.0);
    return std::min(move.scale * footprint.width / shownWidth, move.scale * footprint.height / shownHeight);
}

PictureMove moveClearOf(const Rect& footprint, glm::ivec2 imageSize, const std::vector<Rect>& obstacles, double gap) {
    std::vector<Rect> blocked;
    for (const Rect& obstacle : obstacles) blocked.push_back(inflated(obstacle, gap));
    const auto hits = [&blocked](const Rect& rect) {
        return std::any_of(blocked.begin(), blocked.end(), [&rect](const Rect& b) { return rectsOverlap(rect, b); });
    };
    const glm::dvec2 centre(footprint.x + 0.5 * footprint.width, footprint.y + 0.5 * footprint.height);
    if (!hits(footprint)) return {1.0, centre, centre};

    // The free rectangles: every one whose sides lie on an obstacle's edges or `gap` inside the
    // image's (a moved picture keeps that margin from the image's edges too).
    const glm::dvec2 low(std::min(gap, 0.5 * imageSize.x), std::min(gap, 0.5 * imageSize.y));
    const glm::dvec2 high = glm::dvec2(imageSize) - low;
    std::vector<double> xs{low.x, high.x};
    std::vector<double> ys{low.y, high.y};
    for (const Rect& b : blocked) {
        xs.push_back(std::clamp(b.x, low.x, high.x));
        xs.push_back(std::clamp(b.right(), low.x, high.x));
        ys.push_back(std::clamp(b.y, low.y, high.y));
        ys.push_back(std::clamp(b.bottom(), low.y, high.y));
    }
    PictureMove best{0.0, centre, centre};
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const double x0 : xs)
        for (const double x1 : xs)
            for (const double y0 : ys)
                for (const double y1 : ys) {
                    if (!(x1 > x0 && y1 > y0)) continue;
                    const Rect room{x0, y0, x1 - x0, y1 - y0};
                    if (hits(room)) continue;
                    const double scale = std::min({1.0, room.width / footprint.width, room.height / footprint.height});
                    // The centre nearest to where it was that keeps the scaled footprint in the room.
                    const glm::dvec2 half = 0.5 * scale * glm::dvec2(footprint.width, footprint.height);
                    const glm::dvec2 to{std::clamp(centre.x, room.x + half.x, room.right() - half.x),
                                        std::clamp(centre.y, room.y + half.y, room.bottom() - half.y)};
                    const double distance = glm::length(to - centre);
                    if (scale > best.scale + 1e-9 || (scale > best.scale - 1e-9 && distance < bestDistance)) {
                        best = {scale, centre, to};
                        bestDistance = distance;
                    }
                }
    return best;
}

View movedOnImage(const View& view, glm::ivec2 imageSize, const PictureMove& move) {
    if (move.isIdentity()) return view;
    // Pixels (y down) to normalized device coordinates (y up): x = 2 p / W - 1, y = 1 - 2 p / H.
    const glm::dvec2 shift = move.to - move.scale * move.from;
    glm::dmat4 onImage(1.0);
    onImage[0][0] = move.scale;
    onImage[1][1] = move.scale;
    onImage[3][0] = move.scale - 1.0 + 2.0 * shift.x / imageSize.x;
    onImage[3][1] = 1.0 - move.scale - 2.0 * shift.y / imageSize.y;
    View moved = view;
    moved.projectionMatrix = onImage * view.projectionMatrix;
    return moved;
}

}  // namespace tstyles
