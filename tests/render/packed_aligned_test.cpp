// Fully aligned series are read four time-steps per fetch from the packed atlas
// (render/packed_aligned_atlas.h). Packing must not change what a time-step contributes: a
// known-answer test that needs every channel of both groups, and the benchmark scenes on the
// aligned dataset rendered packed and through the general per-time-step path.
#include <filesystem>
#include <functional>
#include <limits>
#include <variant>

#include <gtest/gtest.h>

#include "bundled_scene_comparison.h"
#include "render_test_support.h"
#include "tstyles/render/packed_aligned_atlas.h"

namespace tstyles::testing {
namespace {


// Six aligned time-steps on a 24x4x4 grid (spacing 0.1): time-step k is dense (1) in the columns
// x = 4k .. 4k + 3 and empty (0) elsewhere, so time-steps 4 and 5 live in the second group.
constexpr int kSteps = 6;
constexpr double kSpacing = 0.1;
Series sixAlignedSteps() {
    std::vector<BoxSpec> boxes;
    for (int k = 0; k < kSteps; ++k) {
        BoxSpec box;
        box.dims = {24, 4, 4};
        box.spacing = glm::dvec3(kSpacing);
        box.density = [k](glm::ivec3 voxel) { return voxel.x / 4 == k ? 1.0f : 0.0f; };
        boxes.push_back(box);
    }
    return makeSeries(boxes);
}

glm::dvec3 indexColour(int step) { return {step / 5.0, 1.0 - step / 5.0, 0.5}; }

// Missing values on uneven levels: the same six time-steps with levels at z = 0, 0.05, 0.15, 0.3
// and no data where `hasData(step, block)` is false (block b: x = 4b .. 4b + 3).
Series sixAlignedStepsWithMissingValues(const std::function<bool(int, int)>& hasData) {
    Series series = sixAlignedSteps();
    for (int k = 0; k < kSteps; ++k) {
        TimeStep& step = series.steps[std::size_t(k)];
        std::get<RectilinearGrid>(step.grid).axisPositions[2] = {0.0, 0.05, 0.15, 0.3};
        for (std::size_t voxel = 0; voxel < step.density.size(); ++voxel)
            if (!hasData(k, int(voxel % 24) / 4)) step.density[voxel] = std::numeric_limits<float>::quiet_NaN();
    }
    return series;
}

// Time-step 0 has no data in blocks 4 and 5 (the packed atlas needs a validity per time-step).
bool stepZeroMissesBlocksFourAndFive(int step, int block) { return step != 0 || block < 4; }
// No time-step has data in block 5 (one validity for all, as land in a weather model).
bool everyStepMissesBlockFive(int, int block) { return block != 5; }

TEST(PackedAtlas, GroupsFourTimeStepsPerTexelInStepOrder) {
    const Series series = sixAlignedSteps();
    ASSERT_TRUE(suitsPackedAtlas(series));
    // Voxel (4k + 1, 0, 0) is dense only in time-step k: channel k % 4 of group k / 4.
    for (int k = 0; k < kSteps; ++k) {
        const std::vector<std::uint16_t> texels = packedGroupTexels(series, std::size_t(k / 4));
        const std::size_t voxel = std::size_t(4 * k + 1);
        for (int channel = 0; channel < 4; ++channel)
            EXPECT_EQ(texels[voxel * 4 + std::size_t(channel)], channel == k % 4 ? 65535 : 0)
                << "time-step " << k << ", channel " << channel;
    }
    // Channels past the last time-step stay 0.
    const std::vector<std::uint16_t> last = packedGroupTexels(series, 1);
    EXPECT_EQ(last[(4 * 5 + 1) * 4 + 2], 0);
    EXPECT_EQ(last[(4 * 5 + 1) * 4 + 3], 0);
}

TEST(PackedAtlas, OnlyAlignedSeriesWithoutMasksArePacked) {
    Series moved = sixAlignedSteps();
    moved.steps[3].placement.origin.x += 0.05;
    EXPECT_FALSE(suitsPackedAtlas(moved));
    Series masked = sixAlignedSteps();
    masked.steps[0].mask.emplace(masked.steps[0].density.size(), std::uint8_t(1));
    EXPECT_FALSE(suitsPackedAtlas(masked));
    Series single = sixAlignedSteps();
    single.steps.resize(1);
    EXPECT_FALSE(suitsPackedAtlas(single));
}

TEST(PackedAtlas, MissingValuesArePremultipliedWithTheirValidityAlongside) {
    EXPECT_EQ(packedValidityOf(sixAlignedSteps()), PackedValidity::None);
    const Series perStep = sixAlignedStepsWithMissingValues(stepZeroMissesBlocksFourAndFive);
    ASSERT_TRUE(suitsPackedAtlas(perStep));
    ASSERT_EQ(packedValidityOf(perStep), PackedValidity::PerGroup);
    // Voxel (21, 0, 0), block 5: time-step 0 (group 0, channel 0) has no data, time-step 1 has 0.
    const std::vector<std::uint16_t> validities = packedGroupValidities(perStep, 0);
    EXPECT_EQ(validities[21 * 4 + 0], 0);
    EXPECT_EQ(validities[21 * 4 + 1], 65535);
    EXPECT_EQ(packedGroupTexels(perStep, 0, true)[21 * 4 + 0], 0);
    // Voxel (1, 0, 0), block 0: time-step 0 is dense there and has data.
    EXPECT_EQ(packedGroupTexels(perStep, 0, true)[1 * 4 + 0], 65535);
    EXPECT_EQ(validities[1 * 4 + 0], 65535);
    // Voxel (21, 0, 0) is dense in time-step 5 (group 1, channel 1), which has data there.
    EXPECT_EQ(packedGroupTexels(perStep, 1, true)[21 * 4 + 1], 65535);

    const Series shared = sixAlignedStepsWithMissingValues(everyStepMissesBlockFive);
    ASSERT_EQ(packedValidityOf(shared), PackedValidity::Shared);
    const std::vector<std::uint16_t> sharedValidity = validityTexels(shared.steps.front());
    EXPECT_EQ(sharedValidity[21], 0);
    EXPECT_EQ(sharedValidity[17], 65535);
    EXPECT_EQ(packedGroupTexels(shared, 1, true)[21 * 4 + 1], 0);
}

TEST(PackedAtlas, UnionOfVisibilitiesIsVisibleWhereAnyTimeStepIs) {
    EXPECT_EQ(unionOfVisibilities({{0, 255, 0, 0}, {0, 0, 0, 255}, {0, 255, 0, 0}}),
              (std::vector<std::uint8_t>{0, 255, 0, 255}));
}

TEST(PackedAtlas, GroupMasksNameTheGroupsVisibleInEachBrick) {
    // Ten time-steps in groups 0-3, 4-7, 8-9; three bricks. Brick 0: time-step 5 visible (group 1);
    // brick 1: none; brick 2: time-steps 0, 3 and 9 (groups 0 and 2).
    std::vector<std::vector<std::uint8_t>> visibilities(10, std::vector<std::uint8_t>(3, 0));
    visibilities[5][0] = 255;
    visibilities[0][2] = 255;
    visibilities[3][2] = 255;
    visibilities[9][2] = 255;
    EXPECT_EQ(groupVisibilityMasks(visibilities), (std::vector<std::uint32_t>{0b010u, 0u, 0b101u}));
    // Groups past the 32 a mask names have no bit: time-step 4 * 32 is in group 32.
    std::vector<std::vector<std::uint8_t>> many(4 * 33, std::vector<std::uint8_t>(1, 0));
    many[4 * 31][0] = 255;
    many[4 * 32][0] = 255;
    EXPECT_EQ(groupVisibilityMasks(many), (std::vector<std::uint32_t>{1u << 31}));
}

// The column-block scenes look down z at the whole 24x4 grid, in a 96x96 image.
constexpr int kColumnImageSize = 96;
constexpr double kGridWidth = 23 * kSpacing;
constexpr double kColumnViewHeight = kGridWidth * 1.1;
const glm::dvec2 kColumnViewCentre(kGridWidth / 2.0, 1.5 * kSpacing);

// Temporal MIP with the index TSTF alone (each time-step's own colour, opaque) over the STF
// opacity given.
Scene columnBlockScene(const std::vector<OpacityNode>& stfOpacity) {
    Scene scene = orthographicSceneLookingDownZ(kColumnViewCentre, kColumnViewHeight, kColumnImageSize);
    scene.compositor = compositorNamed("temporal-mip");
    scene.finalMode = FinalMode::Tstf;
    scene.stf.curve.opacity = stfOpacity;
    scene.stf.curve.color = {{0.0, {1.0, 1.0, 1.0}}};
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color.clear();
    for (int k = 0; k < kSteps; ++k) scene.indexTstf.curve.color.push_back({double(k), indexColour(k)});
    return scene;
}

// At the middle of each column block the colour is that of time-step `expectedWinner(block)`, or
// transparent where that is -1.
void expectWinnerInEveryColumnBlock(const Series& series, const Scene& scene, bool packed, int solo,
                                    const std::function<int(int)>& expectedWinner) {
    FrameOptions options;
    options.packAligned = packed;
    if (solo >= 0) options.soloTimeStep = solo;
    const Image image = renderSeries(series, scene, options);
    for (int block = 0; block < kSteps; ++block) {
        const glm::ivec2 pixel = pixelOf({(4 * block + 1.5) * kSpacing, kColumnViewCentre.y}, kColumnViewCentre,
                                         kColumnViewHeight, kColumnImageSize);
        const glm::vec4 actual = image.at(pixel.x, pixel.y);
        const int winner = expectedWinner(block);
        const glm::vec4 expected = winner >= 0 ? glm::vec4(glm::vec3(indexColour(winner)), 1.0f) : glm::vec4(0.0f);
        for (int channel = 0; channel < 4; ++channel)
            EXPECT_NEAR(actual[channel], expected[channel], 2.0 / 255.0)
                << (packed ? "packed" : "general path") << ", solo " << solo << ", block " << block
                << ", channel " << channel;
    }
}

// Opaque above density 0.5: block k shows time-step k (with one time-step solo, only its block).
TEST(PackedAlignedRender, EveryTimeStepShowsItsIndexColourInItsColumns) {
    const Series series = sixAlignedSteps();
    const Scene scene = columnBlockScene({{0.0, 0.0}, {0.5, 0.0}, {0.51, 1.0}, {1.0, 1.0}});
    for (const bool packed : {true, false})
        for (const int solo : {-1, 4})
            expectWinnerInEveryColumnBlock(series, scene, packed, solo,
                                           [solo](int block) { return solo < 0 || solo == block ? block : -1; });
}

// Opaque below density 0.49, so that a time-step's empty columns show, unless it has no data
// there: in block b every time-step but b is opaque where it has data, and the earliest of them
// wins the tie. A missing value read as density 0 would be opaque and win instead.
TEST(PackedAlignedRender, MissingValuesOnUnevenLevelsAreLeftOut) {
    const Scene scene = columnBlockScene({{0.0, 1.0}, {0.49, 1.0}, {0.5, 0.0}, {1.0, 0.0}});
    for (const auto hasData : {stepZeroMissesBlocksFourAndFive, everyStepMissesBlockFive}) {
        const Series series = sixAlignedStepsWithMissingValues(hasData);
        ASSERT_TRUE(suitsPackedAtlas(series));
        const auto winner = [hasData](int block) {
            for (int k = 0; k < kSteps; ++k)
                if (k != block && hasData(k, block)) return k;
            return -1;
        };
        for (const bool packed : {true, false}) expectWinnerInEveryColumnBlock(series, scene, packed, -1, winner);
    }
}

// The max density change needs every density, also of the groups the group masks name as
// transparent in a brick (read there without STF lookups): time-steps 0-3 are 0 everywhere,
// transparent under the STF in every brick, time-step 4 is 1 and 5 is 0.6, both opaque. The change
// is 1 - 0 = 1 (0.4 if the transparent group were left out), orange on the gradient TSTF.
TEST(PackedAlignedRender, MaxDensityChangeCountsTheGroupTransparentInEveryBrick) {
    std::vector<BoxSpec> boxes;
    for (int k = 0; k < kSteps; ++k) {
        BoxSpec box;
        box.dims = {24, 4, 4};
        box.spacing = glm::dvec3(kSpacing);
        const float density = k == 4 ? 1.0f : k == 5 ? 0.6f : 0.0f;
        box.density = [density](glm::ivec3) { return density; };
        boxes.push_back(box);
    }
    const Series series = makeSeries(boxes);
    Scene scene = columnBlockScene({{0.0, 0.0}, {0.5, 0.0}, {0.55, 1.0}, {1.0, 1.0}});
    scene.compositor = compositorNamed("temporal-max-change");
    scene.gradientTstf.curve.opacity = {{0.0, 1.0}};
    scene.gradientTstf.curve.color = {{0.0, {0, 1, 0}}, {1.0, {1, 0.5, 0}}};  // green to orange
    scene.gradientTstf.rangeLow = 0.0;
    scene.gradientTstf.rangeHigh = 1.0;
    for (const bool packed : {true, false}) {
        FrameOptions options;
        options.packAligned = packed;
        const Image image = renderSeries(series, scene, options);
        for (const double x : {0.5, 1.2, 2.0}) {
            const glm::ivec2 pixel = pixelOf({x, kColumnViewCentre.y}, kColumnViewCentre, kColumnViewHeight,
                                             kColumnImageSize);
            const glm::vec4 actual = image.at(pixel.x, pixel.y);
            const glm::vec4 orange(1.0f, 0.5f, 0.0f, 1.0f);
            for (int channel = 0; channel < 4; ++channel)
                EXPECT_NEAR(actual[channel], orange[channel], 2.0 / 255.0)
                    << (packed ? "packed" : "general path") << ", x " << x << ", channel " << channel;
        }
    }
}

// More groups than a mask names (33 groups, 132 time-steps): the packed walk reads the occupancy
// from its own texture and visits every group. Every time-step is dense in block 0 only, so the
// rays over blocks 1-5 meet empty bricks alone: skipping them takes samples away, and the picture
// is the general path's.
TEST(PackedAlignedRender, WithMoreGroupsThanAMaskNamesTheOccupancyStillSkipsEmptyBricks) {
    constexpr int kManySteps = 4 * (kMaxMaskedGroups + 1);
    std::vector<BoxSpec> boxes;
    for (int k = 0; k < kManySteps; ++k) {
        BoxSpec box;
        box.dims = {24, 4, 4};
        box.spacing = glm::dvec3(kSpacing);
        box.density = [](glm::ivec3 voxel) { return voxel.x < 4 ? 1.0f : 0.0f; };
        boxes.push_back(box);
    }
    const Series series = makeSeries(boxes);
    ASSERT_TRUE(suitsPackedAtlas(series));
    const Scene scene = columnBlockScene({{0.0, 0.0}, {0.5, 0.0}, {0.51, 1.0}, {1.0, 1.0}});
    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    const View view = resolveView(scene.camera, series.worldBounds(), scene.width, scene.height);
    auto draw = [&](bool packed, bool emptyBrickTest) {
        FrameOptions options;
        options.size = {scene.width, scene.height};
        options.collectStatistics = true;
        options.packAligned = packed;
        options.emptyBrickTest = emptyBrickTest;
        renderer.draw(scene, view, options);
        return std::make_pair(renderer.readFrame(), renderer.lastStatistics());
    };
    const auto [skipped, skippedCounts] = draw(true, true);
    const auto [unskipped, unskippedCounts] = draw(true, false);
    const auto [general, generalCounts] = draw(false, true);
    EXPECT_LT(double(skippedCounts.samples), 0.5 * double(unskippedCounts.samples));
    for (const double x : {0.15, 1.2, 2.0}) {
        const glm::ivec2 pixel =
            pixelOf({x, kColumnViewCentre.y}, kColumnViewCentre, kColumnViewHeight, kColumnImageSize);
        for (int channel = 0; channel < 4; ++channel) {
            EXPECT_NEAR(skipped.at(pixel.x, pixel.y)[channel], general.at(pixel.x, pixel.y)[channel], 2.0 / 255.0)
                << "x " << x << ", channel " << channel;
            EXPECT_NEAR(skipped.at(pixel.x, pixel.y)[channel], unskipped.at(pixel.x, pixel.y)[channel], 2.0 / 255.0)
                << "x " << x << ", channel " << channel;
        }
    }
    // Block 0 shows time-step 0 (the earliest wins the tie), the rest is transparent.
    const glm::ivec2 inBlockZero =
        pixelOf({0.15, kColumnViewCentre.y}, kColumnViewCentre, kColumnViewHeight, kColumnImageSize);
    EXPECT_NEAR(skipped.at(inBlockZero.x, inBlockZero.y).a, 1.0f, 2.0 / 255.0);
    const glm::ivec2 inBlockThree =
        pixelOf({1.5, kColumnViewCentre.y}, kColumnViewCentre, kColumnViewHeight, kColumnImageSize);
    EXPECT_NEAR(skipped.at(inBlockThree.x, inBlockThree.y).a, 0.0f, 2.0 / 255.0);
}

// Packed and general path differ only in how a density is fetched (one RGBA16 texel for four
// time-steps instead of one R16 or RG16 texel each, the same 16-bit values and filter weights) and
// in the order in which equal intervals are visited; the images must agree to rounding. Measured
// at 160x160 on llvmpipe (29 November): at most 1/255, mean at most 0.0035/255 (the hurricane).
// None may fail beyond 2/255; mean at most 0.01/255 (three times).
constexpr int kPixelThreshold = 2;
constexpr double kMaxFailingFraction = 0.0;
constexpr double kMaxMeanDelta = 0.01;

class PackedAlignedEquivalence : public ::testing::TestWithParam<BundledScene> {};

TEST_P(PackedAlignedEquivalence, PackedAndGeneralPathGiveTheSameImage) {
    const BundledScene& bundled = GetParam();
    if (!std::filesystem::exists(manifestOf(bundled))) GTEST_SKIP() << "dataset " << bundled.dataset << " is not there";
    ASSERT_TRUE(suitsPackedAtlas(loadSeriesOnce(manifestOf(bundled))));
    FrameOptions general;
    general.packAligned = false;
    expectSameImage(bundled, 160, {"packed", FrameOptions{}, TimeStepWalk::PackedGroups}, {"general", general},
                    {kPixelThreshold, kMaxFailingFraction, kMaxMeanDelta});
}

// The aligned super-ellipsoid (even axes, no missing values) and the hurricane (uneven levels, land
// as missing values shared by every time-step).
INSTANTIATE_TEST_SUITE_P(BenchmarkScenes, PackedAlignedEquivalence,
                         ::testing::Values(BundledScene{"figure4-temporal-mip", "superellipsoid-aligned"},
                                           BundledScene{"figure4-temporal-average", "superellipsoid-aligned"},
                                           BundledScene{"figure4-max-density-change", "superellipsoid-aligned"},
                                           BundledScene{"figure1-styled-focus-step3", "superellipsoid-aligned"},
                                           BundledScene{"figure4-styled-max-density-change", "superellipsoid-aligned"},
                                           BundledScene{"figure5-focus-step5", "hurricane"},
                                           BundledScene{"figure6-left-max-density-change", "hurricane"},
                                           // Every other compositor on the packed path (the
                                           // hurricane's compositor scenes).
                                           BundledScene{"compositors-hurricane-index", "hurricane"},
                                           BundledScene{"compositors-hurricane-signed", "hurricane"},
                                           BundledScene{"compositors-hurricane-spread", "hurricane"}),
                         [](const auto& parameter) { return testNameOf(parameter.param); });

}  // namespace
}  // namespace tstyles::testing
