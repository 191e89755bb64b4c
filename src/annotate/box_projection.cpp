// Which box edges face the viewer, found from which box faces do.
#include "box_projection.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace tstyles {
namespace {

// Whether the face of `axis` at its upper (or lower) end faces the viewer.
bool faceSeen(const View& view, const Bounds& bounds, int axis, bool upper) {
    glm::dvec3 normal(0.0);
    normal[axis] = upper ? 1.0 : -1.0;
    glm::dvec3 onFace = bounds.center();
    onFace[axis] = upper ? bounds.upper[axis] : bounds.lower[axis];
    // An orthographic camera looks along one direction everywhere; a perspective one from its eye.
    const glm::dvec3 toViewer =
        view.projection == Projection::Orthographic ? view.eye - view.target : view.eye - onFace;
    return glm::dot(normal, toViewer) > 0.0;
}

// Distance in front of the eye, along its view direction.
double depthOf(const View& view, const glm::dvec3& point) { return -(view.viewMatrix * glm::dvec4(point, 1.0)).z; }

}  // namespace

std::optional<glm::dvec2> projectToImage(const View& view, glm::ivec2 imageSize, const glm::dvec3& point) {
    const glm::dvec4 clip = view.projectionMatrix * view.viewMatrix * glm::dvec4(point, 1.0);
    if (clip.w <= 1e-9) return std::nullopt;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return glm::dvec2((ndc.x * 0.5 + 0.5) * imageSize.x, (0.5 - ndc.y * 0.5) * imageSize.y);
}

glm::dvec3 boxCorner(const Bounds& bounds, int bits) {
    return {bits & 1 ? bounds.upper.x : bounds.lower.x, bits & 2 ? bounds.upper.y : bounds.lower.y,
            bits & 4 ? bounds.upper.z : bounds.lower.z};
}

std::vector<BoxEdge> tickEdges(const View& view, glm::ivec2 imageSize, const Bounds& bounds, int axis,
                               double shortest) {
    const int first = (axis + 1) % 3;
    const int second = (axis + 2) % 3;
    const double size = glm::length(bounds.upper - bounds.lower);
    // Lexicographic: usable, on the outline, nearer (depth rounded so that mirror images tie), lower.
    using Score = std::tuple<bool, bool, double, double>;
    std::vector<std::pair<Score, BoxEdge>> scored;
    for (int from = 0; from < 8; ++from) {
        if (from & (1 << axis)) continue;
        const glm::dvec3 start = boxCorner(bounds, from);
        const glm::dvec3 end = boxCorner(bounds, from | (1 << axis));
        const auto a = projectToImage(view, imageSize, start);
        const auto b = projectToImage(view, imageSize, end);
        if (!a || !b) continue;
        const glm::dvec2 middle = 0.5 * (*a + *b);
        const bool onImage = middle.x >= 0.0 && middle.y >= 0.0 && middle.x <= imageSize.x && middle.y <= imageSize.y;
        const bool usable = onImage && glm::length(*b - *a) >= shortest;
        const bool outline = faceSeen(view, bounds, first, (from >> first) & 1) !=
                             faceSeen(view, bounds, second, (from >> second) & 1);
        const double nearness = -std::round(depthOf(view, 0.5 * (start + end)) / (1e-6 * size + 1e-300));
        const double lower = axis == 1 ? -middle.x : middle.y;
        scored.push_back({Score{usable, outline, nearness, lower}, BoxEdge{axis, from, *a, *b}});
    }
    std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    std::vector<BoxEdge> edges;
    for (const auto& entry : scored) edges.push_back(entry.second);
    return edges;
}

}  // namespace tstyles
