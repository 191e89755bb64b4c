// Unchanged places (CompositorOptions::unchanged): the compositors that pick a time-step show no
// time colour where a place's densities do not change by more than `below`, nor where two
// time-steps tie (within `tie`). The final image is the TSTF alone over an opaque white STF, so that
// a pixel is white (the STF alone: no time colour), a time-step's pure colour, or transparent.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "stacked_boxes.h"
#include "tstyles/render/raycast_variant.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles::testing {
namespace {

const glm::vec4 kWhite{1, 1, 1, 1};

constexpr TemporalCompositor kPickingCompositors[] = {
    compositorNamed("temporal-mip"), compositorNamed("temporal-min"), compositorNamed("time-of-max"),
    compositorNamed("first-arrival"), compositorNamed("last-above")};
// The two that pick by the highest value.
constexpr TemporalCompositor kPeakPickers[] = {compositorNamed("time-of-max"),
                                               compositorNamed("temporal-mip")};

// An opaque white STF, the TSTF alone, time-step 0 red, 1 green, 2 blue; every time-step reaches
// the threshold of first-arrival and last-above.
Scene pickingScene(TemporalCompositor compositor, std::optional<double> below, double tie = 0.0) {
    Scene scene = orthographicSceneLookingDownZ(kStackCentre, kStackViewHeight, kStackSize);
    scene.stf.curve = constantFunction({1, 1, 1}, 1.0);
    scene.compositor = compositor;
    scene.compositorOptions.values["threshold"] = 0.05;
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
            for (int c = 0; c < 4; ++c) wrong += std::abs(actual[c] - colour[c]) > kStackTolerance ? 1 : 0;
        }
    EXPECT_EQ(wrong, 0) << what;
}

TEST(UnchangedTimeRender, ASeriesConstantOverTimeShowsNoTimeColourAnywhere) {
    const Series series = stackedBoxes({0.5f, 0.5f, 0.5f});
    for (TemporalCompositor compositor : kPickingCompositors) {
        const std::string name = toString(compositor);
        // Without the option the paper's compositors pick a time-step by the tie rules: red or blue.
        const Image everywhere = renderSeries(series, pickingScene(compositor, std::nullopt));
        expectStackPixel(everywhere, kStackCentre, compositor == compositorNamed("last-above") ? kBlue : kRed, name);
        // With the fitted threshold (nothing changes: every place unchanged), no time colour.
        Scene fitted = pickingScene(compositor, 0.0);
        fitted.compositorOptions.unchanged->automatic = true;
        fitted = fitAutomaticParts(fitted, series);
        EXPECT_NEAR(fitted.compositorOptions.unchanged->below, 1e-4, 1e-12) << name;
        EXPECT_EQ(fitted.compositorOptions.unchanged->tie, 0.0) << name;  // three values: no noise estimate
        const Image image = renderSeries(series, fitted);
        expectStackPixel(image, kStackCentre, kWhite, name);
        expectOnly(image, kWhite, name);
    }
}

TEST(UnchangedTimeRender, TiesNeverChooseAColour) {
    // Time-steps 0 and 2 share the highest density (and, under the opaque STF, the highest opacity):
    // with thresholds of 0, only the tie itself shows no time colour.
    const Series peakTwice = stackedBoxes({0.8f, 0.3f, 0.8f});
    for (TemporalCompositor compositor : kPeakPickers)
        expectStackPixel(renderSeries(peakTwice, pickingScene(compositor, 0.0)), kStackCentre, kWhite,
                         toString(compositor));
    expectStackPixel(renderSeries(stackedBoxes({0.3f, 0.8f, 0.3f}), pickingScene(compositorNamed("temporal-min"), 0.0)),
                kStackCentre, kWhite, "temporal-min, a tie of the lowest");
    // Ahead by 0.05: a colour with a tie of 0.04, none with 0.06.
    const Series peakOnce = stackedBoxes({0.8f, 0.3f, 0.85f});
    for (TemporalCompositor compositor : kPeakPickers) {
        const std::string name = toString(compositor);
        expectStackPixel(renderSeries(peakOnce, pickingScene(compositor, 0.0, 0.04)), kStackCentre, kBlue, name);
        expectStackPixel(renderSeries(peakOnce, pickingScene(compositor, 0.0, 0.06)), kStackCentre, kWhite, name);
    }
    const Series lowOnce = stackedBoxes({0.35f, 0.8f, 0.3f});
    const TemporalCompositor minimum = compositorNamed("temporal-min");
    expectStackPixel(renderSeries(lowOnce, pickingScene(minimum, 0.0, 0.04)), kStackCentre, kBlue, "temporal-min");
    expectStackPixel(renderSeries(lowOnce, pickingScene(minimum, 0.0, 0.06)), kStackCentre, kWhite, "temporal-min");
    // A tie shows as an unchanged place does: transparent where they are.
    Scene tiedTransparent = pickingScene(compositorNamed("time-of-max"), 0.0);
    tiedTransparent.compositorOptions.unchanged->opacity = 0.0;
    expectStackPixel(renderSeries(peakTwice, tiedTransparent), kStackCentre, kTransparent,
                     "a tie, unchanged places transparent");
}

TEST(UnchangedTimeRender, ArrivalsShowTimeWhereTheRangeExceedsTheThreshold) {
    // Densities 0.2, 0.6, 0.9: a range of 0.7. First arrival at 0.5 is time-step 1 where the
    // threshold is below 0.7, and no time colour at 0.7 and above ("by no more than").
    const Series series = stackedBoxes({0.2f, 0.6f, 0.9f});
    Scene arrival = pickingScene(compositorNamed("first-arrival"), 0.65);
    arrival.compositorOptions.values["threshold"] = 0.5;
    expectStackPixel(renderSeries(series, arrival), kStackCentre, kGreen, "first-arrival, threshold 0.65");
    arrival.compositorOptions.unchanged->below = 0.75;
    expectStackPixel(renderSeries(series, arrival), kStackCentre, kWhite, "first-arrival, threshold 0.75");
    Scene departure = pickingScene(compositorNamed("last-above"), 0.65);
    departure.compositorOptions.values["threshold"] = 0.5;
    expectStackPixel(renderSeries(series, departure), kStackCentre, kBlue, "last-above, threshold 0.65");
    departure.compositorOptions.unchanged->below = 0.75;
    expectStackPixel(renderSeries(series, departure), kStackCentre, kWhite, "last-above, threshold 0.75");
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
    Scene faint = pickingScene(compositorNamed("temporal-mip"), 0.0);
    faint.compositorOptions.unchanged->opacity = 0.25;
    const float opacity = float(slabOpacity(0.25, kConstantBoxWidth));
    expectStackPixel(renderSeries(series, faint), kStackCentre, glm::vec4(opacity, opacity, opacity, opacity),
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
    Scene scene = pickingScene(compositorNamed("first-arrival"), 0.1);
    scene.compositorOptions.values["threshold"] = 0.5;
    scene.compositorOptions.unchanged->gain = 2.0;
    scene.stf.curve = constantFunction({1, 1, 1}, 0.25);
    scene.finalMode = FinalMode::Modulate;
    const float changed = float(slabOpacity(1.0 - 0.75 * 0.75, kConstantBoxWidth));
    expectStackPixel(renderSeries(stackedBoxes({0.2f, 0.6f, 0.9f}), scene), kStackCentre,
                glm::vec4(0.0f, changed, 0.0f, changed), "changes: as if twice as thick");
    const float unchanged = float(slabOpacity(0.25, kConstantBoxWidth));
    expectStackPixel(renderSeries(stackedBoxes({0.6f, 0.6f, 0.6f}), scene), kStackCentre,
                glm::vec4(unchanged, unchanged, unchanged, unchanged), "unchanged: as the STF has it");
}

TEST(UnchangedTimeRender, UnchangedPlacesKeepTheirBoundaries) {
    // Three equal time-steps of a ramp along x, 0.1 + 0.05 per voxel 0.1 apart: a value gradient of
    // 0.5 per unit length everywhere. With boundary 1 an unchanged place is halfway from a flat
    // interior (a quarter of its share) to a boundary (all of it): 0.625 of the STF's 0.25 per
    // reference length, over the box's 7.
    BoxSpec box;
    box.density = [](glm::ivec3 voxel) { return float(0.1 + 0.05 * voxel.x); };
    const Series series = makeSeries({box, box, box});
    Scene scene = pickingScene(compositorNamed("temporal-mip"), 0.1);
    scene.stf.curve = constantFunction({1, 1, 1}, 0.25);
    scene.finalMode = FinalMode::Modulate;
    scene.compositorOptions.unchanged->boundary = 1.0;
    const float halfway = float(slabOpacity(0.25 * 0.625, kConstantBoxWidth));
    expectStackPixel(renderSeries(series, scene), kStackCentre, glm::vec4(halfway, halfway, halfway, halfway),
                     "halfway where the gradient is half the boundary's");
    scene.compositorOptions.unchanged->boundary = 0.25;  // steeper than the boundary: the whole share
    const float whole = float(slabOpacity(0.25, kConstantBoxWidth));
    expectStackPixel(renderSeries(series, scene), kStackCentre, glm::vec4(whole, whole, whole, whole),
                     "the whole share where the gradient is steeper than the boundary");
    // A box of one value: a flat interior keeps a quarter of the share.
    scene.compositorOptions.unchanged->boundary = 1.0;
    const float interior = float(slabOpacity(0.25 * 0.25, kConstantBoxWidth));
    expectStackPixel(renderSeries(stackedBoxes({0.5f, 0.5f, 0.5f}), scene), kStackCentre,
                     glm::vec4(interior, interior, interior, interior), "a flat interior");
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
    Scene picking = pickingScene(compositorNamed("temporal-mip"), 0.0);
    picking.camera = orthographicSceneLookingDownZ(centre, viewHeight, kStackSize).camera;
    picking.compositorOptions.unchanged->automatic = true;
    for (TemporalCompositor compositor : kPeakPickers) {
        picking.compositor = compositor;
        Scene fitted = fitAutomaticParts(picking, series);
        // Changes of 0.6 on the path and 0 elsewhere; three values are too few for noise: 0.06.
        EXPECT_NEAR(fitted.compositorOptions.unchanged->below, 0.06, 1e-6);
        EXPECT_EQ(fitted.compositorOptions.unchanged->tie, 0.0);
        // 384 visible places, 144 of them on the path: rays through the path are cbrt(384 / 144)
        // times shorter.
        EXPECT_NEAR(fitted.compositorOptions.unchanged->gain, std::cbrt(384.0 / 144.0), 1e-9);
        // The steepest value gradient of time-step 0 in a hundred places: (0.9 - 0.3) / 0.1 one-sided
        // at the box's face beside the slab (1 column of 24). The colours are checked without it.
        EXPECT_NEAR(fitted.compositorOptions.unchanged->boundary, 6.0, 1e-4);
        fitted.compositorOptions.unchanged->boundary = 0.0;
        const auto at = [&](int voxelX) { return pixelOf({0.1 * voxelX, 0.15}, centre, viewHeight, kStackSize); };
        // Each walk over the time-steps: the packed groups (the series is aligned), the ray's list, naive.
        for (const auto& [walk, options] :
             {std::pair{TimeStepWalk::PackedGroups, FrameOptions{}}, std::pair{TimeStepWalk::RayList, rayList()},
              std::pair{TimeStepWalk::Naive, naive()}}) {
            const Image image = renderSeries(series, fitted, options);
            ASSERT_EQ(testRenderer().lastVariant().walk, walk);
            ASSERT_TRUE(testRenderer().lastVariant().unchangedTime);
            const std::string name = toString(compositor) + ", " + walkName(walk);
            expectPixelNear(image, at(2), kRed, name + ", time-step 0's slab");
            expectPixelNear(image, at(6), kGreen, name + ", time-step 1's slab");
            expectPixelNear(image, at(10), kBlue, name + ", time-step 2's slab");
            for (int never = 13; never <= 22; ++never)
                expectPixelNear(image, at(never), kWhite, name + ", never reached");
        }
        // Without the option the never-reached background takes time-step 0's colour by the tie.
        Scene everywhere = fitted;
        everywhere.compositorOptions.unchanged.reset();
        expectPixelNear(renderSeries(series, everywhere), at(14), kRed, toString(compositor) + ", without the option");
        EXPECT_FALSE(testRenderer().lastVariant().unchangedTime);
    }
}

}  // namespace
}  // namespace tstyles::testing
