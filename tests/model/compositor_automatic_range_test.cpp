// The automatic ("auto") gradient TSTF range of each compositor that the gradient TSTF reads,
// from the series' typical largest change C and its time span T (AutomaticRange).
#include <gtest/gtest.h>

#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

// Two time-steps of one box, density 0.2 then 0.6 everywhere (a change C = 0.4), at times 10 and 14.
Series risingBox() {
    Series series;
    series.valueRange = {0.0, 1.0};
    const double times[] = {10.0, 14.0};
    const float densities[] = {0.2f, 0.6f};
    for (int index = 0; index < 2; ++index) {
        TimeStep step;
        step.time = times[index];
        step.grid = RectilinearGrid{glm::ivec3(4), glm::dvec3(0.1)};
        step.rawRange = {0.0, 1.0};
        step.density.assign(step.rectilinear().voxelCount(), densities[index]);
        series.steps.push_back(std::move(step));
    }
    return series;
}

std::pair<double, double> rangeFor(TemporalCompositor compositor, const Series& series) {
    Scene scene;
    scene.stf.curve.opacity = {{0.0, 1.0}};  // every voxel visible
    scene.compositor = compositor;
    return automaticGradientRange(scene, series);
}

TEST(CompositorAutomaticRange, FitsEachCompositorsCharacteristic) {
    const Series series = risingBox();
    Scene visible;
    visible.stf.curve.opacity = {{0.0, 1.0}};
    const double change = typicalLargestChange(series, visible.stf);
    ASSERT_NEAR(change, 0.4, 1e-6);
    const auto expectRange = [&](TemporalCompositor compositor, double low, double high) {
        const auto [actualLow, actualHigh] = rangeFor(compositor, series);
        EXPECT_NEAR(actualLow, low, 1e-9) << toString(compositor);
        EXPECT_NEAR(actualHigh, high, 1e-9) << toString(compositor);
    };
    expectRange(compositorNamed("temporal-max-change"), 0.0, change);
    expectRange(compositorNamed("temporal-std-dev"), 0.0, change / 2);  // values spread over C deviate at most C / 2
    expectRange(compositorNamed("difference"), -change, change);
    expectRange(compositorNamed("linear-trend"), -change / 4.0, change / 4.0);  // a change of C over the 4 time units
    expectRange(kCustomCompositor, 0.0, change);
}

TEST(CompositorAutomaticRange, ATrendOnOneInstantFallsBackToTheChange) {
    Series series = risingBox();
    series.steps[1].time = series.steps[0].time;
    const auto [low, high] = rangeFor(compositorNamed("linear-trend"), series);
    EXPECT_NEAR(high, 0.4, 1e-6);
    EXPECT_NEAR(low, -0.4, 1e-6);
}

}  // namespace
}  // namespace tstyles
