// The table of temporal compositors (paper 5.3 and the ones users of temporal data ask for).
#include "tstyles/scene/temporal_compositors.h"

#include <array>
#include <stdexcept>

namespace tstyles {
namespace {

// The enumerators are brought in inside the initialiser only: CompositorReads shares names with
// the TSTF types, and the file is compiled in one unity file with others.
constexpr std::array kCompositors = [] {
    using enum TemporalCompositor;
    using enum CompositorReads;
    using enum AutomaticRange;
    using Info = TemporalCompositorInfo;
    return std::array{
        Info{MaxIntensityProjection, "temporal-mip", "tc_max_intensity_projection.glsl", IndexTstf, Change, false,
             false, true, "the time-step with the highest STF opacity, by the index TSTF"},
        Info{Average, "temporal-average", "tc_average.glsl", Composited, Change, false, false,
             false, "colours and opacities averaged over the visible time-steps"},
        Info{MaxDensityChange, "temporal-max-change", "tc_max_density_change.glsl", GradientTstf, Change, false,
             false, false, "largest minus smallest density, by the gradient TSTF"},
        Info{Minimum, "temporal-min", "tc_minimum.glsl", IndexTstf, Change, false, false,
             true, "the time-step with the lowest density, by the index TSTF"},
        Info{StandardDeviation, "temporal-std-dev", "tc_standard_deviation.glsl", GradientTstf, HalfChange, false,
             false, false, "standard deviation of the densities, by the gradient TSTF"},
        Info{TimeOfMaximum, "time-of-max", "tc_time_of_maximum.glsl", IndexTstf, Change, false, false,
             true, "the time-step of the highest density (time to peak), by the index TSTF"},
        Info{FirstArrival, "first-arrival", "tc_first_arrival.glsl", IndexTstf, Change, true, false,
             true, "the first time-step at or above the threshold, by the index TSTF"},
        Info{LastAbove, "last-above", "tc_last_above.glsl", IndexTstf, Change, true, false,
             true, "the last time-step at or above the threshold, by the index TSTF"},
        Info{LinearTrend, "linear-trend", "tc_linear_trend.glsl", GradientTstf, SignedPerTime, false, false,
             false, "least-squares slope of density over time, by the gradient TSTF"},
        Info{Chronovolume, "chronovolume", "tc_chronovolume.glsl", Composited, Change, false, false,
             false, "the time-steps composited front to back in time order"},
        Info{Difference, "difference", "tc_difference.glsl", GradientTstf, SignedChange, false, true,
             false, "density of one time-step minus another's, by the gradient TSTF"},
        Info{Custom, "custom", "", IndexTstf, Change, false, false,
             false, "the scene's own GLSL over the time-steps at the sample"},
    };
}();

}  // namespace

std::span<const TemporalCompositorInfo> temporalCompositors() { return kCompositors; }

const TemporalCompositorInfo& compositorInfo(TemporalCompositor compositor) {
    for (const auto& info : kCompositors)
        if (info.compositor == compositor) return info;
    throw std::logic_error("a temporal compositor without a line in the table");
}

CompositorReads compositorReads(const Scene& scene) {
    if (scene.compositor == TemporalCompositor::Custom && scene.compositorOptions.custom)
        return scene.compositorOptions.custom->reads;
    return compositorInfo(scene.compositor).reads;
}

}  // namespace tstyles
