// Unchanged places (CompositorOptions::unchanged): the compositors that pick a time-step show no
// time colour where a place's densities do not change by more than `below`, nor where two
// time-steps tie (within `tie`). The final image is the TSTF alone over an opaque white STF, so that
// a pixel is white (the STF alone: no time colour), a time-step's pure colour, or transparent.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/render/raycast_variant.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 64;
constexpr double kViewHeight = 2.0;
const glm::dvec2 kCentre(0.35, 0.35);
// As in compositor_render_test.cpp: 16-bit densities, 1024-entry tables, float arithmetic.
constexpr float kTolerance = 2e-3f;

const glm::vec4 kRed{1, 0, 0, 1};
const glm::vec4 kGreen{0, 1, 0, 1};
const glm::vec4 kBlue{0, 0, 1, 1};
const glm::vec4 kWhite{1, 1, 1, 1};
const glm::vec4 kTransparent{0, 0, 0, 0};

constexpr TemporalCompositor kPickingCompositors[] = {
    TemporalCompositor::MaxIntensityProjection, TemporalCompositor::Minimum, TemporalCompositor::TimeOfMaximum,
    TemporalCompositor::FirstArrival, TemporalCompositor::LastAbove};

void expectPixelAt(const Image& image, glm::ivec2 pixel, glm::vec4 expected, const std::string& what) {
    const glm::vec4 actual = image.at(pixel.x, pixel.y);
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(actual[c], expected[c], kTolerance)
            << what << " at pixel (" << pixel.x << ", " << pixel.y << ") channel " << c;
}

void expectPixel(const Image& image, glm::dvec2 world, glm::vec4 expected, const std::string& what) {
    expectPixelAt(image, pixelOf(world, kCentre, kViewHeight, kSize), expected, what);
}

Series stackedBoxes(const std::vector<float>& densities) {
    std::vector<BoxSpec> boxes;
    for (float density : densities) boxes.push_back(constantBox({0, 0, 0}, density));
    return makeSeries(boxes);
}

// An opaque white STF, the TSTF alone, time-step 0 red, 1 green, 2 blue; every time-step reaches
// the threshold of first-arrival and last-above.
Scene pickingScene(TemporalCompositor compositor, std::optional<double> below, double tie = 0.0) {
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({1, 1, 1}, 1.0);
    scene.compositor = compositor;
    scene.compositorOptions.threshold = 0.05;
    scene.finalMode = FinalMode::Tstf;
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}, {2.0, {0, 0, 1}}};
    if (below) {
        UnchangedTime unchanged;
        unchanged.automatic = false;
        unchanged.below = *below;
        unchanged.tie = tie;
        scene.compositorOptions.unchanged = unchanged;
    }
    return scene;
}

// Every pixel is either transparent or `colour`.
void expectOnly(const Image& image, glm::vec4 colour, const std::string& what) {
    int wrong = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4 actual = image.at(x, y);
            if (actual.a == 0.0f) continue;
            for (int c = 0; c < 4; ++c) wrong += std::abs(actual[c] - colour[c]) > kTolerance ? 1 : 0;
        }
    EXPECT_EQ(wrong, 0) << what;
}

TEST(UnchangedTimeRender, ASeriesConstantOverTimeShowsNoTimeColourAnywhere) {
    const Series series = stackedBoxes({0.5f, 0.5f, 0.5f});
    for (TemporalCompositor compositor : kPickingCompositors) {
        const std::string name = toString(compositor);
        // Without the option the paper's compositors pick a time-step by the tie rules: red or blue.
        const Image everywhere = renderSeries(series, pickingScene(compositor, std::nullopt));
        expectPixel(everywhere, kCentre, compositor == TemporalCompositor::LastAbove ? kBlue : kRed, name);
        // With the fitted threshold (nothing changes: every place unchanged), no time colour.
        Scene fitted = pickingScene(compositor, 0.0);
        fitted.compositorOptions.unchanged->automatic = true;
        fitted = fitAutomaticParts(fitted, series);
        EXPECT_NEAR(fitted.compositorOptions.unchanged->below, 1e-4, 1e-12) << name;
        EXPECT_EQ(fitted.compositorOptions.unchanged->tie, 0.0) << name;  // three values: no noise estimate
        const Image image = renderSeries(series, fitted);
        expectPixel(image, kCentre, kWhite, name);
        expectOnly(image, kWhite, name);
    }
}

TEST(UnchangedTimeRender, TiesNeverChooseAColour) {
    // Time-steps 0 and 2 share the highest density (and, under the opaque STF, the highest opacity):
    // with thresholds of 0, only the tie itself shows no time colour.
    const Series peakTwice = stackedBoxes({0.8f, 0.3f, 0.8f});
    for (TemporalCompositor compositor : {TemporalCompositor::TimeOfMaximum, TemporalCompositor::MaxIntensityProjection})
        expectPixel(renderSeries(peakTwice, pickingScene(compositor, 0.0)), kCentre, kWhite, toString(compositor));
    expectPixel(renderSeries(stackedBoxes({0.3f, 0.8f, 0.3f}), pickingScene(TemporalCompositor::Minimum, 0.0)),
                kCentre, kWhite, "temporal-min, a tie of the lowest");
    // Ahead by 0.05: a colour with a tie of 0.04, none with 0.06.
    const Series peakOnce = stackedBoxes({0.8f, 0.3f, 0.85f});
    for (TemporalCompositor compositor : {TemporalCompositor::TimeOfMaximum, TemporalCompositor::MaxIntensityProjection}) {
        expectPixel(renderSeries(peakOnce, pickingScene(compositor, 0.0, 0.04)), kCentre, kBlue, toString(compositor));
        expectPixel(renderSeries(peakOnce, pickingScene(compositor, 0.0, 0.06)), kCentre, kWhite, toString(compositor));
    }
    const Series lowOnce = stackedBoxes({0.35f, 0.8f, 0.3f});
    expectPixel(renderSeries(lowOnce, pickingScene(TemporalCompositor::Minimum, 0.0, 0.04)), kCentre, kBlue,
                "temporal-min");
    expectPixel(renderSeries(lowOnce, pickingScene(TemporalCompositor::Minimum, 0.0, 0.06)), kCentre, kWhite,
                "temporal-min");
    // A tie shows as an unchanged place does: transparent where they are.
    Scene tiedTransparent = pickingScene(TemporalCompositor::TimeOfMaximum, 0.0);
    tiedTransparent.compositorOptions.unchanged->opacity = 0.0;
    expectPixel(renderSeries(peakTwice, tiedTransparent), kCentre, kTransparent, "a tie, unchanged places transparent");
}

TEST(UnchangedTimeRender, ArrivalsShowTimeWhereTheRangeExceedsTheThreshold) {
    // Densities 0.2, 0.6, 0.9: a range of 0.7. First arrival at 0.5 is time-step 1 where the
    // threshold is below 0.7, and no time colour at 0.7 and above ("by no more than").
    const Series series = stackedBoxes({0.2f, 0.6f, 0.9f});
    Scene arrival = pickingScene(TemporalCompositor::FirstArrival, 0.65);
    arrival.compositorOptions.threshold = 0.5;
    expectPixel(renderSeries(series, arrival), kCentre, kGreen, "first-arrival, threshold 0.65");
    arrival.compositorOptions.unchanged->below = 0.75;
    expectPixel(renderSeries(series, arrival), kCentre, kWhite, "first-arrival, threshold 0.75");
    Scene departure = pickingScene(TemporalCompositor::LastAbove, 0.65);
    departure.compositorOptions.threshold = 0.5;
    expectPixel(renderSeries(series, departure), kCentre, kBlue, "last-above, threshold 0.65");
    departure.compositorOptions.unchanged->below = 0.75;
    expectPixel(renderSeries(series, departure), kCentre, kWhite, "last-above, threshold 0.75");
}

TEST(UnchangedTimeRender, UnchangedPlacesKeepTheirShareOfTheStfsOpacity) {
    const Series series = stackedBoxes({0.5f, 0.5f, 0.5f});
    for (TemporalCompositor compositor : kPickingCompositors) {
        Scene scene = pickingScene(compositor, 0.0);
        scene.compositorOptions.unchanged->opacity = 0.0;
        expectOnly(renderSeries(series, scene), kTransparent, toString(compositor));
    }
    // A quarter of the opacity per reference length: a slab of the box's width (7 reference
    // lengths) gathers 1 - 0.75^7 (Beer-Lambert with the renderer's opacity correction), white.
    Scene faint = pickingScene(TemporalCompositor::MaxIntensityProjection, 0.0);
    faint.compositorOptions.unchanged->opacity = 0.25;
    const float opacity = float(slabOpacity(0.25, kConstantBoxWidth));
    expectPixel(renderSeries(series, faint), kCentre, glm::vec4(opacity, opacity, opacity, opacity),
                "a quarter of the STF's opacity, premultiplied");
}

FrameOptions rayList() {
    FrameOptions options;
    options.packAligned = false;
    return options;
}

FrameOptions naive() {
    FrameOptions options;
    options.naive = true;
    return options;
}

TEST(UnchangedTimeRender, PlacesThatChangeShowAsIfGainTimesAsThick) {
    // STF opacity 0.25 per reference length modulated by an opaque index TSTF: a place that changes
    // (first arrival at time-step 1, green) gathers 1 - 0.75^2 per reference length with a gain of 2,
    // over the box's 7 reference lengths; an unchanged one (a constant series) 0.25, as the STF has it.
    Scene scene = pickingScene(TemporalCompositor::FirstArrival, 0.1);
    scene.compositorOptions.threshold = 0.5;
    scene.compositorOptions.unchanged->gain = 2.0;
    scene.stf.curve = constantFunction({1, 1, 1}, 0.25);
    scene.finalMode = FinalMode::Modulate;
    const float changed = float(slabOpacity(1.0 - 0.75 * 0.75, kConstantBoxWidth));
    expectPixel(renderSeries(stackedBoxes({0.2f, 0.6f, 0.9f}), scene), kCentre,
                glm::vec4(0.0f, changed, 0.0f, changed), "changes: as if twice as thick");
    const float unchanged = float(slabOpacity(0.25, kConstantBoxWidth));
    expectPixel(renderSeries(stackedBoxes({0.6f, 0.6f, 0.6f}), scene), kCentre,
                glm::vec4(unchanged, unchanged, unchanged, unchanged), "unchanged: as the STF has it");
}

TEST(UnchangedTimeRender, AMovingBlobColoursOnlyItsPath) {
    // 24 x 4 x 4 voxels 0.1 apart over a background of 0.3; at time-step i a slab three voxels wide
    // (x = 1 + 4 i .. 3 + 4 i, through the whole depth) holds 0.9, so that it passes over fewer than
    // half of the places (the fitted noise is that of the others: none). Seen from above, the slab's
    // middle column at each time shows that time-step's colour; the columns it never reaches (13 to
    // 22; 23 is the box's edge) are white.
    std::vector<BoxSpec> boxes;
    for (int step = 0; step < 3; ++step) {
        BoxSpec box;
        box.dims = {24, 4, 4};
        box.density = [step](glm::ivec3 voxel) {
            return voxel.x >= 1 + 4 * step && voxel.x <= 3 + 4 * step ? 0.9f : 0.3f;
        };
        boxes.push_back(box);
    }
    const Series series = makeSeries(boxes);
    const glm::dvec2 centre(1.15, 0.15);
    const double viewHeight = 2.6;
    Scene picking = pickingScene(TemporalCompositor::MaxIntensityProjection, 0.0);
    picking.camera = orthographicSceneLookingDownZ(centre, viewHeight, kSize).camera;
    picking.compositorOptions.unchanged->automatic = true;
    for (TemporalCompositor compositor : {TemporalCompositor::MaxIntensityProjection, TemporalCompositor::TimeOfMaximum}) {
        picking.compositor = compositor;
        const Scene fitted = fitAutomaticParts(picking, series);
        // Changes of 0.6 on the path and 0 elsewhere; three values are too few for noise: 0.06.
        EXPECT_NEAR(fitted.compositorOptions.unchanged->below, 0.06, 1e-6);
        EXPECT_EQ(fitted.compositorOptions.unchanged->tie, 0.0);
        // 384 visible places, 144 of them on the path: rays through the path are cbrt(384 / 144)
        // times shorter.
        EXPECT_NEAR(fitted.compositorOptions.unchanged->gain, std::cbrt(384.0 / 144.0), 1e-9);
        const auto at = [&](int voxelX) { return pixelOf({0.1 * voxelX, 0.15}, centre, viewHeight, kSize); };
        // Each walk over the time-steps: the packed groups (the series is aligned), the ray's list, naive.
        for (const auto& [walk, options] :
             {std::pair{TimeStepWalk::PackedGroups, FrameOptions{}}, std::pair{TimeStepWalk::RayList, rayList()},
              std::pair{TimeStepWalk::Naive, naive()}}) {
            const Image image = renderSeries(series, fitted, options);
            ASSERT_EQ(testRenderer().lastVariant().walk, walk);
            ASSERT_TRUE(testRenderer().lastVariant().unchangedTime);
            const std::string name = toString(compositor) + ", " + walkName(walk);
            expectPixelAt(image, at(2), kRed, name + ", time-step 0's slab");
            expectPixelAt(image, at(6), kGreen, name + ", time-step 1's slab");
            expectPixelAt(image, at(10), kBlue, name + ", time-step 2's slab");
            for (int never = 13; never <= 22; ++never) expectPixelAt(image, at(never), kWhite, name + ", never reached");
        }
        // Without the option the never-reached background takes time-step 0's colour by the tie.
        Scene everywhere = fitted;
        everywhere.compositorOptions.unchanged.reset();
        expectPixelAt(renderSeries(series, everywhere), at(14), kRed, toString(compositor) + ", without the option");
        EXPECT_FALSE(testRenderer().lastVariant().unchangedTime);
    }
}

}  // namespace
}  // namespace tstyles::testing
