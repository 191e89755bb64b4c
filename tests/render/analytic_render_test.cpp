// Renders compared with closed-form expectations: Beer-Lambert attenuation, the temporal
// compositors on constant boxes, masks and early ray termination.
#include <cmath>

#include <gtest/gtest.h>

#include "render_test_support.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 64;
constexpr double kViewHeight = 2.0;
constexpr double kBoxWidth = kConstantBoxWidth;
// Densities pass through 16-bit textures and the transfer functions through 1024-entry tables;
// the remaining error is float arithmetic along the ray.
constexpr float kTolerance = 2e-3f;

void expectPixel(const Image& image, glm::ivec2 pixel, glm::vec4 expected, const char* what) {
    const glm::vec4 actual = image.at(pixel.x, pixel.y);
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(actual[c], expected[c], kTolerance)
            << what << " at pixel (" << pixel.x << ", " << pixel.y << ") channel " << c;
}

TEST(AnalyticRender, BeerLambertThroughAConstantSlab) {
    const Series series = makeSeries({constantBox({0.0, 0.0, 0.0}, 1.0f)});
    const glm::dvec2 centre(0.35, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    const glm::dvec3 color(1.0, 0.5, 0.25);
    const double alpha = 0.05;
    scene.stf.curve = constantFunction(color, alpha);
    scene.finalMode = FinalMode::Stf;

    const double expectedAlpha = slabOpacity(alpha, kBoxWidth);  // 1 - 0.95^7
    const glm::vec4 expected(glm::vec3(color * expectedAlpha), float(expectedAlpha));
    for (double step : {0.05, 0.013, 0.1}) {  // opacity correction makes the step irrelevant
        scene.raycast.step = step;
        const Image image = renderSeries(series, scene);
        expectPixel(image, pixelOf(centre, centre, kViewHeight, kSize), expected, "slab centre");
        expectPixel(image, pixelOf({0.1, 0.6}, centre, kViewHeight, kSize), expected, "slab corner");
        expectPixel(image, pixelOf({-0.4, 0.35}, centre, kViewHeight, kSize), glm::vec4(0.0f), "beside the slab");
    }
}

TEST(AnalyticRender, BeerLambertThroughARotatedSlabUsesTheTrueThickness) {
    // Rotated 90 degrees about y, the box still spans 0.7 along z: same attenuation.
    BoxSpec box = constantBox({0.0, 0.0, 0.7}, 1.0f);
    box.rotation = glm::angleAxis(glm::radians(90.0), glm::dvec3(0.0, 1.0, 0.0));
    const Series series = makeSeries({box});
    const glm::dvec2 centre(0.35, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({0.0, 1.0, 0.0}, 0.1);
    scene.finalMode = FinalMode::Stf;
    const double expectedAlpha = slabOpacity(0.1, kBoxWidth);
    const Image image = renderSeries(series, scene);
    expectPixel(image, pixelOf(centre, centre, kViewHeight, kSize),
                glm::vec4(0.0f, float(expectedAlpha), 0.0f, float(expectedAlpha)), "rotated slab");
}

TEST(AnalyticRender, DisjointBoxesShowTheirIndexTstfColours) {
    const Series series = makeSeries({constantBox({0.0, 0.0, 0.0}, 1.0f), constantBox({1.0, 0.0, 0.0}, 1.0f)});
    const glm::dvec2 centre(0.85, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({1.0, 1.0, 1.0}, 1.0);
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1.0, 0.0, 0.0}}, {1.0, {0.0, 1.0, 0.0}}};
    scene.finalMode = FinalMode::Tstf;
    for (auto compositor : {compositorNamed("temporal-mip"), compositorNamed("temporal-average")}) {
        scene.compositor = compositor;
        const Image image = renderSeries(series, scene);
        expectPixel(image, pixelOf({0.35, 0.35}, centre, kViewHeight, kSize), {1, 0, 0, 1}, "time-step 0");
        expectPixel(image, pixelOf({1.35, 0.35}, centre, kViewHeight, kSize), {0, 1, 0, 1}, "time-step 1");
        expectPixel(image, pixelOf({0.85, 0.35}, centre, kViewHeight, kSize), {0, 0, 0, 0}, "the gap");
    }
}

TEST(AnalyticRender, TemporalMaximumIntensityProjectionTakesTheMostOpaqueTimeStep) {
    const Series series = makeSeries({constantBox({0, 0, 0}, 0.3f), constantBox({0, 0, 0}, 0.8f),
                                      constantBox({0, 0, 0}, 0.5f)});
    const glm::dvec2 centre(0.35, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 0.0}, {1.0, 1.0}};  // opacity = density
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}, {2.0, {0, 0, 1}}};
    scene.finalMode = FinalMode::Tstf;
    scene.compositor = compositorNamed("temporal-mip");
    const Image image = renderSeries(series, scene);
    expectPixel(image, pixelOf(centre, centre, kViewHeight, kSize), {0, 1, 0, 1}, "time-step 1 wins");
}

TEST(AnalyticRender, TemporalAverageOverThreeFullyOverlappingSteps) {
    const float densities[3] = {0.2f, 0.5f, 0.8f};
    const Series series = makeSeries({constantBox({0, 0, 0}, densities[0]), constantBox({0, 0, 0}, densities[1]),
                                      constantBox({0, 0, 0}, densities[2])});
    const glm::dvec2 centre(0.35, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    // STF: opacity 0.1 * density, colour from blue (density 0) to red (density 1).
    scene.stf.curve.opacity = {{0.0, 0.0}, {1.0, 0.1}};
    scene.stf.curve.color = {{0.0, {0, 0, 1}}, {1.0, {1, 0, 0}}};
    scene.compositor = compositorNamed("temporal-average");
    scene.finalMode = FinalMode::Stf;

    // Per sample: opacities averaged, colours averaged weighted by opacity.
    double opacitySum = 0.0;
    glm::dvec3 weightedColor(0.0);
    for (float density : densities) {
        const double opacity = 0.1 * density;
        opacitySum += opacity;
        weightedColor += opacity * glm::dvec3(density, 0.0, 1.0 - density);
    }
    const double sampleOpacity = opacitySum / 3.0;
    const glm::dvec3 sampleColor = weightedColor / opacitySum;
    const double alpha = slabOpacity(sampleOpacity, kBoxWidth);
    const Image image = renderSeries(series, scene);
    expectPixel(image, pixelOf(centre, centre, kViewHeight, kSize),
                glm::vec4(glm::vec3(sampleColor * alpha), float(alpha)), "average of three");
}

TEST(AnalyticRender, MaxDensityChangeReadsTheGradientTstfWhereStepsOverlapAndTheStfElsewhere) {
    const float a = 0.3f;
    const float b = 0.9f;
    // Box 0 spans x in [0, 0.7], box 1 spans x in [0.35, 1.05]: they overlap in [0.35, 0.7].
    const Series series = makeSeries({constantBox({0, 0, 0}, a), constantBox({0.35, 0, 0}, b)});
    const glm::dvec2 centre(0.525, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 1.0}};
    scene.stf.curve.color = {{0.0, {0, 0, 0}}, {1.0, {1, 1, 1}}};  // grey level = density
    scene.gradientTstf.curve.opacity = {{0.0, 1.0}};
    scene.gradientTstf.curve.color = {{0.0, {0, 1, 0}}, {1.0, {1, 0.5, 0}}};  // green to orange
    scene.gradientTstf.rangeLow = 0.0;
    scene.gradientTstf.rangeHigh = 1.0;
    scene.compositor = compositorNamed("temporal-max-change");
    scene.finalMode = FinalMode::Tstf;
    const Image image = renderSeries(series, scene);

    const double change = b - a;  // 0.6
    const glm::vec4 changeColor(float(change), float(1.0 - 0.5 * change), 0.0f, 1.0f);
    expectPixel(image, pixelOf({0.525, 0.35}, centre, kViewHeight, kSize), changeColor, "overlap");
    expectPixel(image, pixelOf({0.15, 0.35}, centre, kViewHeight, kSize), {a, a, a, 1}, "box 0 alone: STF");
    expectPixel(image, pixelOf({0.9, 0.35}, centre, kViewHeight, kSize), {b, b, b, 1}, "box 1 alone: STF");

    // The range rescales the change: [0.5, 0.7] maps 0.6 to the middle of the TSTF.
    scene.gradientTstf.rangeLow = 0.5;
    scene.gradientTstf.rangeHigh = 0.7;
    const Image rescaled = renderSeries(series, scene);
    expectPixel(rescaled, pixelOf({0.525, 0.35}, centre, kViewHeight, kSize), {0.5f, 0.75f, 0.0f, 1.0f},
                "rescaled change");
}

TEST(AnalyticRender, AMaskSplitsABoxBetweenTstfInsideAndStfOutside) {
    BoxSpec box = constantBox({0, 0, 0}, 1.0f);
    box.mask = [](glm::ivec3 voxel) { return voxel.x < 4; };  // the half with x < 0.35
    const Series series = makeSeries({box});
    const glm::dvec2 centre(0.35, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({0, 0, 1}, 1.0);
    scene.indexTstf.curve = constantFunction({1, 0, 0}, 1.0);
    scene.finalMode = FinalMode::Tstf;
    for (auto compositor : {compositorNamed("temporal-mip"), compositorNamed("temporal-average")}) {
        scene.compositor = compositor;
        const Image image = renderSeries(series, scene);
        expectPixel(image, pixelOf({0.1, 0.35}, centre, kViewHeight, kSize), {1, 0, 0, 1}, "inside the mask: TSTF");
        expectPixel(image, pixelOf({0.6, 0.35}, centre, kViewHeight, kSize), {0, 0, 1, 1}, "outside the mask: STF");
    }
}

TEST(AnalyticRender, EarlyRayTerminationStopsAtTheFirstOpaqueBox) {
    // Box 0 lies in front (z in [1, 1.7]) of box 1 (z in [0, 0.7]); the camera looks down -z.
    const Series series = makeSeries({constantBox({0, 0, 1.0}, 1.0f), constantBox({0, 0, 0}, 1.0f)});
    const glm::dvec2 centre(0.35, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({1, 1, 1}, 0.5);  // 1 - 0.5^7 = 0.992 through box 0
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}};
    scene.finalMode = FinalMode::Modulate;
    scene.raycast.step = 0.05;
    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    const View view = resolveView(scene.camera, series.worldBounds(), kSize, kSize);
    FrameOptions options;
    options.size = {kSize, kSize};
    options.collectStatistics = true;
    const glm::ivec2 pixel = pixelOf(centre, centre, kViewHeight, kSize);

    scene.raycast.termination = 0.99;
    renderer.draw(scene, view, options);
    const glm::vec4 terminated = renderer.readFrame().at(pixel.x, pixel.y);
    const RaycastStatistics early = renderer.lastStatistics();
    EXPECT_GE(terminated.a, 0.99f);
    EXPECT_EQ(terminated.g, 0.0f) << "nothing of box 1 may show";
    // Every ray through box 0 stops within its 0.7 / 0.05 = 14 samples.
    EXPECT_LE(double(early.samples) / double(early.rays), 14.0);

    scene.raycast.termination = 1.0;  // never reached: rays run to their end
    renderer.draw(scene, view, options);
    const glm::vec4 full = renderer.readFrame().at(pixel.x, pixel.y);
    const RaycastStatistics late = renderer.lastStatistics();
    EXPECT_GT(full.g, 0.0f) << "without termination box 1 contributes";
    EXPECT_GE(double(late.samples) / double(late.rays), 28.0);
}

TEST(AnalyticRender, RaysThatMeetNothingShowTheBackground) {
    const Series series = makeSeries({constantBox({0, 0, 0}, 1.0f)});
    const glm::dvec2 centre(5.0, 5.0);  // looking far beside the box
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.background = {0.2, 0.4, 0.6, 1.0};
    const Image image = renderSeries(series, scene);
    expectPixel(image, {kSize / 2, kSize / 2}, {0.2f, 0.4f, 0.6f, 1.0f}, "background");
}

}  // namespace
}  // namespace tstyles::testing

namespace tstyles::testing {
namespace {

TEST(AnalyticRender, ASoloTimeStepShowsThatTimeStepAlone) {
    const Series series = makeSeries({constantBox({0.0, 0.0, 0.0}, 1.0f), constantBox({1.0, 0.0, 0.0}, 1.0f)});
    const glm::dvec2 centre(0.85, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({1.0, 1.0, 1.0}, 1.0);
    scene.finalMode = FinalMode::Stf;
    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    FrameOptions options;
    options.size = {kSize, kSize};
    options.soloTimeStep = 1;
    renderer.draw(scene, resolveView(scene.camera, series.worldBounds(), kSize, kSize), options);
    const Image image = renderer.readFrame();
    expectPixel(image, pixelOf({0.35, 0.35}, centre, kViewHeight, kSize), {0, 0, 0, 0}, "time-step 0 hidden");
    expectPixel(image, pixelOf({1.35, 0.35}, centre, kViewHeight, kSize), {1, 1, 1, 1}, "time-step 1 alone");
}

}  // namespace
}  // namespace tstyles::testing

namespace tstyles::testing {
namespace {

TEST(AnalyticRender, TemporalMipBreaksOpacityTiesInFavourOfTheMoreVisibleTimeStep) {
    // Equal STF opacity everywhere; the index TSTF shows time-step 1 more strongly.
    const Series series = makeSeries({constantBox({0, 0, 0}, 1.0f), constantBox({0, 0, 0}, 1.0f),
                                      constantBox({0, 0, 0}, 1.0f)});
    const glm::dvec2 centre(0.35, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({1, 1, 1}, 1.0);
    scene.indexTstf.curve.opacity = {{0.0, 0.2}, {1.0, 1.0}, {2.0, 0.2}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}, {2.0, {0, 0, 1}}};
    scene.finalMode = FinalMode::Tstf;
    scene.compositor = compositorNamed("temporal-mip");
    const Image image = renderSeries(series, scene);
    expectPixel(image, pixelOf(centre, centre, kViewHeight, kSize), {0, 1, 0, 1}, "time-step 1 wins the tie");
}

}  // namespace
}  // namespace tstyles::testing
