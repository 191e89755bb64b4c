// The parts of the raycasting pass that `bench --stages` times (RaycastPart) and the pass clocks
// (FrameOptions::timePasses): the march takes the whole pass' samples but for early termination,
// on each walk, and leaves the picture transparent; the ray setup takes no sample.
#include <cmath>

#include <gtest/gtest.h>

#include "render_test_support.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 32;
constexpr double kViewHeight = 2.0;

struct PartFrame {
    Image image;
    RaycastStatistics statistics;
    RaycastVariant variant;
};

PartFrame drawPart(const Series& series, const Scene& scene, RaycastPart part) {
    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    FrameOptions options;
    options.size = {kSize, kSize};
    options.collectStatistics = true;
    options.raycastPart = part;
    renderer.draw(scene, resolveView(scene.camera, series.worldBounds(), kSize, kSize), options);
    return {renderer.readFrame(), renderer.lastStatistics(), renderer.lastVariant()};
}

// Two opaque boxes seen from above; `apart`: box 0 (z in [1, 1.7]) in front of box 1 (z in
// [0, 0.7]) with a gap between, else both at the same place (a fully aligned, packed series).
Scene opaqueBoxesScene(glm::dvec2 centre, double termination) {
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({1, 1, 1}, 0.5);
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}};
    scene.finalMode = FinalMode::Modulate;
    scene.raycast.step = 0.05;
    scene.raycast.termination = termination;
    return scene;
}

void expectMarchTakesTheWholePassSamples(const Series& series, glm::dvec2 centre, TimeStepWalk walk,
                                         double samplesPerRayWithoutTermination) {
    // Without termination (1.0 is never reached) the march takes exactly the whole pass' samples:
    // the same lattice and the same jumps between time-steps.
    const PartFrame whole = drawPart(series, opaqueBoxesScene(centre, 1.0), RaycastPart::Whole);
    const PartFrame march = drawPart(series, opaqueBoxesScene(centre, 1.0), RaycastPart::March);
    ASSERT_EQ(whole.variant.walk, walk);
    ASSERT_EQ(march.variant.walk, walk);
    ASSERT_EQ(march.variant.part, RaycastPart::March);
    EXPECT_GT(whole.statistics.rays, 0u);
    EXPECT_EQ(march.statistics.rays, whole.statistics.rays);
    EXPECT_EQ(march.statistics.samples, whole.statistics.samples);
    EXPECT_NEAR(double(march.statistics.samples) / double(march.statistics.rays), samplesPerRayWithoutTermination,
                1.0);

    // With termination at 0.9 the whole pass stops after 7 samples (1 - 0.5^(7 * 0.5) = 0.91); the
    // march, which composites nothing, runs on to the exit and leaves the pixel transparent.
    const PartFrame terminated = drawPart(series, opaqueBoxesScene(centre, 0.9), RaycastPart::Whole);
    const PartFrame marchOnly = drawPart(series, opaqueBoxesScene(centre, 0.9), RaycastPart::March);
    EXPECT_LT(terminated.statistics.samples, whole.statistics.samples);
    EXPECT_EQ(marchOnly.statistics.samples, whole.statistics.samples);
    const glm::ivec2 pixel = pixelOf(centre, centre, kViewHeight, kSize);
    EXPECT_GE(terminated.image.at(pixel.x, pixel.y).a, 0.9f);
    EXPECT_LT(marchOnly.image.at(pixel.x, pixel.y).a, 1e-6f);
}

TEST(RaycastParts, TheMarchTakesTheWholePassSamplesOnTheRayList) {
    // 14 samples in each box (0.7 / 0.05), none in the gap between them.
    const Series series = makeSeries({constantBox({0, 0, 1.0}, 1.0f), constantBox({0, 0, 0}, 1.0f)});
    expectMarchTakesTheWholePassSamples(series, {0.35, 0.35}, TimeStepWalk::RayList, 28.0);
}

TEST(RaycastParts, TheMarchTakesTheWholePassSamplesOnThePackedGroups) {
    const Series series = makeSeries({constantBox({0, 0, 0}, 1.0f), constantBox({0, 0, 0}, 1.0f)});
    expectMarchTakesTheWholePassSamples(series, {0.35, 0.35}, TimeStepWalk::PackedGroups, 14.0);
}

TEST(RaycastParts, TheRaySetupTakesNoSample) {
    const Series series = makeSeries({constantBox({0, 0, 1.0}, 1.0f), constantBox({0, 0, 0}, 1.0f)});
    const PartFrame setup = drawPart(series, opaqueBoxesScene({0.35, 0.35}, 0.99), RaycastPart::RaySetup);
    ASSERT_EQ(setup.variant.part, RaycastPart::RaySetup);
    EXPECT_EQ(setup.statistics.samples, 0u);
    const glm::ivec2 pixel = pixelOf({0.35, 0.35}, {0.35, 0.35}, kViewHeight, kSize);
    EXPECT_LT(setup.image.at(pixel.x, pixel.y).a, 1e-6f);
}

TEST(RaycastParts, PassClocksMeasureEveryPass) {
    const Series series = makeSeries({constantBox({0, 0, 1.0}, 1.0f), constantBox({0, 0, 0}, 1.0f)});
    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    const Scene scene = opaqueBoxesScene({0.35, 0.35}, 0.99);
    const View view = resolveView(scene.camera, series.worldBounds(), kSize, kSize);
    FrameOptions options;
    options.size = {kSize, kSize};
    options.timePasses = true;
    renderer.draw(scene, view, options);
    const FramePassTimes times = renderer.lastPassTimes();
    EXPECT_GT(times.entryExitMs, 0.0);
    EXPECT_GT(times.raycastMs, 0.0);
    EXPECT_TRUE(std::isfinite(times.entryExitMs) && std::isfinite(times.raycastMs));
    // Timing leaves the picture alone.
    const Image timed = renderer.readFrame();
    options.timePasses = false;
    renderer.draw(scene, view, options);
    const Image untimed = renderer.readFrame();
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) ASSERT_EQ(timed.at(x, y), untimed.at(x, y)) << x << ", " << y;
}

}  // namespace
}  // namespace tstyles::testing
