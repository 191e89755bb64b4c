// Ray set-up from the view matrices, slab clipping against the series' bounds, and the march.
#include "volume_picking.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "tstyles/data/density_sampling.h"

namespace tstyles::viewer {
namespace {

struct Ray {
    glm::dvec3 origin;
    glm::dvec3 direction;
};

// The ray through a pixel centre, from the near plane, as the raycaster builds it.
Ray rayThroughPixel(const View& view, glm::dvec2 pixel, glm::ivec2 viewport) {
    const glm::dmat4 inverse = glm::inverse(view.projectionMatrix * view.viewMatrix);
    const glm::dvec2 ndc{(pixel.x + 0.5) / viewport.x * 2.0 - 1.0, 1.0 - (pixel.y + 0.5) / viewport.y * 2.0};
    const glm::dvec4 nearPoint = inverse * glm::dvec4(ndc, -1.0, 1.0);
    const glm::dvec4 farPoint = inverse * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 origin = glm::dvec3(nearPoint) / nearPoint.w;
    return {origin, glm::normalize(glm::dvec3(farPoint) / farPoint.w - origin)};
}

// The ray parameters where it is inside the box, if it meets it.
std::optional<std::pair<double, double>> clipToBounds(const Ray& ray, const Bounds& bounds) {
    double enter = 0.0;
    double leave = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(ray.direction[axis]) < 1e-12) {
            if (ray.origin[axis] < bounds.lower[axis] || ray.origin[axis] > bounds.upper[axis]) return std::nullopt;
            continue;
        }
        double a = (bounds.lower[axis] - ray.origin[axis]) / ray.direction[axis];
        double b = (bounds.upper[axis] - ray.origin[axis]) / ray.direction[axis];
        if (a > b) std::swap(a, b);
        enter = std::max(enter, a);
        leave = std::min(leave, b);
    }
    if (enter > leave) return std::nullopt;
    return std::make_pair(enter, leave);
}

bool isVisible(const Series& series, const Scene& scene, const glm::dvec3& position) {
    for (const TimeStep& step : series.steps) {
        const std::optional<double> density = sampleDensity(step, position);
        if (density && !isMissing(*density) && scene.stf.curve.evaluate(*density).opacity >= kVisibleOpacity) return true;
    }
    return false;
}

}  // namespace

std::optional<Pick> pickFirstVisibleSample(const Series& series, const Scene& scene, glm::dvec2 pixel,
                                           glm::ivec2 viewport, double stepLength) {
    if (series.size() == 0 || viewport.x <= 0 || viewport.y <= 0 || !(stepLength > 0.0)) return std::nullopt;
    const View view = resolveView(scene.camera, series.worldBounds(), viewport.x, viewport.y);
    const Ray ray = rayThroughPixel(view, pixel, viewport);
    const auto range = clipToBounds(ray, series.worldBounds());
    if (!range) return std::nullopt;
    // A bound on the work for absurd steps: a pick is a click, it must answer at once.
    const double step = std::max(stepLength, (range->second - range->first) / 20000.0);
    for (double t = range->first; t <= range->second; t += step) {
        const glm::dvec3 position = ray.origin + t * ray.direction;
        if (isVisible(series, scene, position)) return Pick{pixel, position, temporalProfile(series, position)};
    }
    return std::nullopt;
}

}  // namespace tstyles::viewer
