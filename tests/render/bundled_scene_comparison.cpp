// Two renderings of a bundled scene compared (bundled_scene_comparison.h).
#include "bundled_scene_comparison.h"

#include <iostream>
#include <optional>
#include <utility>

#include <gtest/gtest.h>

#include "tstyles/image/image_comparison.h"
#include "render_test_support.h"
#include "tstyles/image/image_io.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::testing {
namespace {

const std::filesystem::path kSourceDir = TSTYLES_SOURCE_DIR;
const std::filesystem::path kOutputDir = TSTYLES_TEST_OUTPUT_DIR;

// The renderer took the paths `way` forces (FrameOptions falls back silently where a path does not
// suit the series: a forced comparison that compared the default path with itself would pass).
void expectPathsTaken(const RenderingWay& way, const RaycastVariant& taken) {
    const FrameOptions& options = way.options;
    if (options.naive) {
        EXPECT_EQ(taken.walk, TimeStepWalk::Naive) << way.name << ": the naive walk";
    }
    if (!options.packAligned) {
        EXPECT_NE(taken.walk, TimeStepWalk::PackedGroups) << way.name << ": the general path";
    }
    if (way.walk) {
        EXPECT_EQ(taken.walk, *way.walk) << way.name << ": took the " << walkName(taken.walk) << " walk, not the "
                                         << walkName(*way.walk);
    }
    if (options.perRayCaches) {
        EXPECT_EQ(taken.perRayCaches, *options.perRayCaches) << way.name << ": per-ray caches";
    }
    if (options.emptyBrickTest) {
        EXPECT_EQ(taken.skipEmptyBricks, *options.emptyBrickTest) << way.name << ": the empty-brick test";
    }
    if (options.precomputedGradients && taken.styled()) {
        EXPECT_EQ(taken.precomputedGradients, *options.precomputedGradients)
            << way.name << ": " << (*options.precomputedGradients ? "the gradient atlas" : "six-fetch gradients");
    }
}

// Both ways with the same gradient method unless one of them chooses it.
std::pair<RenderingWay, RenderingWay> withOneGradientMethod(RenderingWay first, RenderingWay second) {
    if (!first.options.precomputedGradients && !second.options.precomputedGradients) {
        first.options.precomputedGradients = false;
        second.options.precomputedGradients = false;
    }
    return {first, second};
}

}  // namespace

void PrintTo(const BundledScene& bundled, std::ostream* out) {
    *out << bundled.scene << " on " << bundled.dataset;
    if (!bundled.compositor.empty()) *out << " with " << bundled.compositor;
}

std::string testNameOf(const BundledScene& bundled) {
    std::string name = bundled.scene + "_on_" + bundled.dataset;
    if (!bundled.compositor.empty()) name += "_with_" + bundled.compositor;
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

std::filesystem::path manifestOf(const BundledScene& bundled) {
    return kSourceDir / "data" / bundled.dataset / "series.json";
}

void expectSameImage(const BundledScene& bundled, int size, const RenderingWay& firstWay,
                     const RenderingWay& secondWay, const SameImageTolerance& tolerance) {
    const auto [first, second] = withOneGradientMethod(firstWay, secondWay);
    Scene scene = loadScene(kSourceDir / "data/scenes" / (bundled.scene + ".json"));
    scene.width = size;
    scene.height = size;
    if (!bundled.compositor.empty()) {
        const std::optional<TemporalCompositor> compositor = temporalCompositorFromString(bundled.compositor);
        ASSERT_TRUE(compositor) << "no compositor named " << bundled.compositor;
        scene.compositor = *compositor;
    }
    const Series& series = loadSeriesOnce(manifestOf(bundled));
    testRenderer().setSeries(series);
    const Image firstImage = drawWithCurrentSeries(scene, series.worldBounds(), first.options);
    expectPathsTaken(first, testRenderer().lastVariant());
    const Image secondImage = drawWithCurrentSeries(scene, series.worldBounds(), second.options);
    expectPathsTaken(second, testRenderer().lastVariant());

    const ImageDifference difference = compareImages(firstImage, secondImage, tolerance.pixelThreshold);
    const bool same = difference.failingFraction <= tolerance.maxFailingFraction &&
                      difference.meanDelta <= tolerance.maxMeanDelta;
    const std::string name = bundled.scene + "." + bundled.dataset;
    if (!same) {
        std::filesystem::create_directories(kOutputDir);
        writeImage(firstImage, kOutputDir / (name + "." + first.name + ".png"));
        writeImage(secondImage, kOutputDir / (name + "." + second.name + ".png"));
        writeImage(differenceImage(firstImage, secondImage, 8.0f),
                   kOutputDir / (name + "." + first.name + "-" + second.name + ".difference.png"));
    }
    std::cout << "  " << bundled.scene << " on " << bundled.dataset << ", " << first.name << " against "
              << second.name << ": " << describe(difference) << "\n";
    EXPECT_TRUE(same) << bundled.scene << " on " << bundled.dataset << ", " << first.name << " against "
                      << second.name << ": " << describe(difference);
}

}  // namespace tstyles::testing
