// Ray set-up from the view matrices, slab clipping against the series' bounds, and one march per
// ProbeDepth over the samples' temporal profiles.
#include "volume_picking.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

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

// One sample of the march: where, the exposed time-steps' densities there (missing and outside
// left out), and the same per exposed time-step (NaN for those).
struct RaySample {
    glm::dvec3 position;
    std::vector<double> densities;
    std::vector<double> byStep;
};

// The opacity a composited sample adds: its most opaque time-step's STF opacity, with the
// unchanged-places share where the compositor takes it, corrected to the step.
class SampleOpacity {
public:
    SampleOpacity(const Scene& scene, double stepLength, double referenceLength)
        : scene_(scene),
          unchanged_(compositorInfo(scene.compositor).takesUnchanged ? scene.compositorOptions.unchanged
                                                                      : std::nullopt),
          exponent_(stepLength / referenceLength) {}

    double operator()(const std::vector<double>& densities) const {
        double opacity = 0.0;
        for (const double density : densities) opacity = std::max(opacity, scene_.stf.curve.evaluate(density).opacity);
        if (unchanged_ && !densities.empty()) {
            const auto [lowest, highest] = std::minmax_element(densities.begin(), densities.end());
            opacity = *highest - *lowest <= unchanged_->below ? opacity * unchanged_->opacity
                                                              : 1.0 - std::pow(1.0 - opacity, unchanged_->gain);
        }
        return 1.0 - std::pow(1.0 - std::clamp(opacity, 0.0, 1.0), exponent_);
    }

private:
    const Scene& scene_;
    std::optional<UnchangedTime> unchanged_;
    double exponent_;
};

bool stfShows(const Scene& scene, double density) { return scene.stf.curve.evaluate(density).opacity > 0.0; }

// Where some time-step's density crosses an iso-value between two samples: the place between
// them, linearly; none if none crosses (a time-step missing at either sample crosses nothing).
std::optional<glm::dvec3> crossingBetween(const RaySample& before, const RaySample& after,
                                          const std::vector<double>& isoValues) {
    std::optional<double> nearest;  // fraction of the way from `before` to `after`
    for (std::size_t step = 0; step < before.byStep.size(); ++step)
        for (const double iso : isoValues) {
            const double a = before.byStep[step];
            const double b = after.byStep[step];
            if (std::isnan(a) || std::isnan(b) || (a < iso) == (b < iso)) continue;
            const double fraction = (iso - a) / (b - a);
            nearest = std::min(nearest.value_or(1.0), fraction);
        }
    if (!nearest) return std::nullopt;
    return before.position + *nearest * (after.position - before.position);
}

// A reduction along the ray: the place of the sample that scores highest (ties: the nearest).
class BestSample {
public:
    void offer(double score, const glm::dvec3& position) {
        if (!best_ || score > score_) {
            best_ = position;
            score_ = score;
        }
    }
    std::optional<glm::dvec3> place() const { return best_; }

private:
    std::optional<glm::dvec3> best_;
    double score_ = 0.0;
};

}  // namespace

std::optional<glm::dvec3> probePlaceUnder(const Series& series, const Scene& scene, glm::dvec2 pixel,
                                          glm::ivec2 viewport, double stepLength, double referenceLength) {
    if (series.size() == 0 || viewport.x <= 0 || viewport.y <= 0 || !(stepLength > 0.0) || !(referenceLength > 0.0))
        return std::nullopt;
    const View view = resolveView(scene.camera, series.worldBounds(), viewport.x, viewport.y);
    const Ray ray = rayThroughPixel(view, pixel, viewport);
    const auto range = clipToBounds(ray, series.worldBounds());
    if (!range) return std::nullopt;
    const glm::ivec2 exposed = scene.exposure.stepsOf(series.size());
    const TemporalProfiler profiler(series);
    // A bound on the work for absurd steps: a pick is a click, it must answer at once.
    const double step = std::max(stepLength, (range->second - range->first) / 20000.0);
    const ProbeDepth depth = rayModeInfo(scene.rayMode).probeDepth;
    const SampleOpacity sampleOpacity(scene, step, referenceLength);
    const RayModeOption* isoOption = rayModeInfo(scene.rayMode).options.find("values");
    const std::vector<double> isoValues = isoOption ? scene.rayOptions.numbers(*isoOption) : std::vector<double>{};

    double transmittance = 1.0;
    BestSample best;
    std::optional<RaySample> previous;
    for (double t = range->first; t <= range->second; t += step) {
        RaySample sample{ray.origin + t * ray.direction, {}, {}};
        const std::vector<std::optional<double>> profile = profiler.profile(sample.position);
        for (int index = exposed.x; index <= exposed.y; ++index) {
            const auto& density = profile[std::size_t(index)];
            const bool present = density && !isMissing(*density);
            if (present) sample.densities.push_back(*density);
            sample.byStep.push_back(present ? *density : std::numeric_limits<double>::quiet_NaN());
        }
        if (sample.densities.empty()) {
            previous.reset();
            continue;
        }
        const auto [lowest, highest] = std::minmax_element(sample.densities.begin(), sample.densities.end());
        switch (depth) {
            case ProbeDepth::HalfOpacity:
                transmittance *= 1.0 - sampleOpacity(sample.densities);
                if (transmittance <= 0.5) return sample.position;
                break;
            case ProbeDepth::LargestValue:
                if (stfShows(scene, *highest)) best.offer(*highest, sample.position);
                break;
            case ProbeDepth::SmallestValue:
                for (const double density : sample.densities)
                    if (stfShows(scene, density)) best.offer(-density, sample.position);
                break;
            case ProbeDepth::LargestChange:
                best.offer(*highest - *lowest, sample.position);
                break;
            case ProbeDepth::FirstCrossing:
                if (previous)
                    if (const auto crossing = crossingBetween(*previous, sample, isoValues)) return crossing;
                break;
        }
        previous = std::move(sample);
    }
    return best.place();
}

}  // namespace tstyles::viewer
