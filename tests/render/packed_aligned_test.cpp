// Fully aligned series are read four time-steps per fetch from the packed atlas
// (render/packed_aligned_atlas.h). Packing must not change what a time-step contributes: a
// known-answer test that needs every channel of both groups, and the benchmark scenes on the
// aligned dataset rendered packed and through the general per-time-step path.
#include <iostream>

#include <gtest/gtest.h>

#include "image_comparison.h"
#include "render_test_support.h"
#include "tstyles/data/manifest.h"
#include "tstyles/image/image_io.h"
#include "tstyles/render/packed_aligned_atlas.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::testing {
namespace {

const std::filesystem::path kSourceDir = TSTYLES_SOURCE_DIR;
const std::filesystem::path kOutputDir = TSTYLES_TEST_OUTPUT_DIR;

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

TEST(PackedAtlas, UnionOfVisibilitiesIsVisibleWhereAnyTimeStepIs) {
    EXPECT_EQ(unionOfVisibilities({{0, 255, 0, 0}, {0, 0, 0, 255}, {0, 255, 0, 0}}),
              (std::vector<std::uint8_t>{0, 255, 0, 255}));
}

// Temporal MIP with an opaque STF above density 0.5 and the index TSTF alone: each column block
// shows its time-step's colour, fully opaque; with one time-step solo, only its block shows.
TEST(PackedAlignedRender, EveryTimeStepShowsItsIndexColourInItsColumns) {
    const Series series = sixAlignedSteps();
    constexpr int kSize = 96;
    const double width = 23 * kSpacing;
    const glm::dvec2 centre(width / 2.0, 1.5 * kSpacing);
    const double viewHeight = width * 1.1;
    Scene scene = orthographicSceneLookingDownZ(centre, viewHeight, kSize);
    scene.compositor = TemporalCompositor::MaxIntensityProjection;
    scene.finalMode = FinalMode::Tstf;
    scene.stf.curve.opacity = {{0.0, 0.0}, {0.5, 0.0}, {0.51, 1.0}, {1.0, 1.0}};
    scene.stf.curve.color = {{0.0, {1.0, 1.0, 1.0}}};
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color.clear();
    for (int k = 0; k < kSteps; ++k) scene.indexTstf.curve.color.push_back({double(k), indexColour(k)});

    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    const View view = resolveView(scene.camera, series.worldBounds(), kSize, kSize);
    for (const bool packed : {true, false}) {
        for (const int solo : {-1, 4}) {
            FrameOptions options;
            options.size = {kSize, kSize};
            options.packAligned = packed;
            if (solo >= 0) options.soloTimeStep = solo;
            renderer.draw(scene, view, options);
            const Image image = renderer.readFrame();
            for (int k = 0; k < kSteps; ++k) {
                // The middle of time-step k's dense block: x = (4k + 1.5) voxels.
                const glm::ivec2 pixel =
                    pixelOf({(4 * k + 1.5) * kSpacing, centre.y}, centre, viewHeight, kSize);
                const glm::vec4 actual = image.at(pixel.x, pixel.y);
                const bool shown = solo < 0 || solo == k;
                const glm::vec4 expected = shown ? glm::vec4(glm::vec3(indexColour(k)), 1.0f) : glm::vec4(0.0f);
                for (int channel = 0; channel < 4; ++channel)
                    EXPECT_NEAR(actual[channel], expected[channel], 2.0 / 255.0)
                        << (packed ? "packed" : "general path") << ", solo " << solo << ", time-step " << k
                        << ", channel " << channel;
            }
        }
    }
}

// Packed and general path differ only in how a density is fetched (one RGBA16 texel for four
// time-steps instead of one R16 texel each, the same 16-bit values and filter weights) and in the
// order in which equal intervals are visited; the images must agree to rounding.
constexpr int kPixelThreshold = 2;
constexpr double kMaxFailingFraction = 0.001;
constexpr double kMaxMeanDelta = 0.05;

class PackedAlignedEquivalence : public ::testing::TestWithParam<std::string> {};

TEST_P(PackedAlignedEquivalence, PackedAndGeneralPathGiveTheSameImage) {
    const std::string& sceneName = GetParam();
    const std::filesystem::path manifest = kSourceDir / "data/superellipsoid-aligned/series.json";
    if (!std::filesystem::exists(manifest)) GTEST_SKIP() << "dataset superellipsoid-aligned is not there";
    const Scene scene = loadScene(kSourceDir / "data/scenes" / (sceneName + ".json"));
    const Series& series = loadSeriesOnce(manifest);
    ASSERT_TRUE(suitsPackedAtlas(series));
    constexpr int kSize = 160;
    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    const View view = resolveView(scene.camera, series.worldBounds(), kSize, kSize);
    FrameOptions options;
    options.size = {kSize, kSize};
    renderer.draw(scene, view, options);
    const Image packed = renderer.readFrame();
    options.packAligned = false;
    renderer.draw(scene, view, options);
    const Image general = renderer.readFrame();

    const ImageDifference difference = compareImages(packed, general, kPixelThreshold);
    const bool same = difference.failingFraction <= kMaxFailingFraction && difference.meanDelta <= kMaxMeanDelta;
    if (!same) {
        std::filesystem::create_directories(kOutputDir);
        writeImage(packed, kOutputDir / (sceneName + ".packed.png"));
        writeImage(general, kOutputDir / (sceneName + ".general.png"));
        writeImage(differenceImage(packed, general, 8.0f), kOutputDir / (sceneName + ".packed-difference.png"));
    }
    std::cout << "  " << sceneName << ": " << describe(difference) << "\n";
    EXPECT_TRUE(same) << sceneName << ": " << describe(difference);
}

INSTANTIATE_TEST_SUITE_P(BenchmarkScenes, PackedAlignedEquivalence,
                         ::testing::Values("figure4-temporal-mip", "figure4-temporal-average",
                                           "figure4-max-density-change", "figure1-styled-focus-step3",
                                           "figure4-styled-max-density-change"),
                         [](const auto& parameter) {
                             std::string name = parameter.param;
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

}  // namespace
}  // namespace tstyles::testing
