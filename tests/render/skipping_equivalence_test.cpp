// Speed-ups must not change images: each benchmark scene rendered by the optimised raycaster
// (per-ray time-step lists, gap jumps, empty-space skipping) and by the naive one (every time-step
// tested at every sample, nothing skipped) gives the same picture.
#include <iostream>
#include <map>
#include <ostream>

#include <gtest/gtest.h>

#include "image_comparison.h"
#include "render_test_support.h"
#include "tstyles/data/manifest.h"
#include "tstyles/image/image_io.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::testing {
namespace {

const std::filesystem::path kSourceDir = TSTYLES_SOURCE_DIR;
const std::filesystem::path kOutputDir = TSTYLES_TEST_OUTPUT_DIR;
constexpr int kSize = 160;
// After a skip the samples of a ray sit at other positions along it (a shift of less than one
// step); on the steep density edges of the super-ellipsoid that moves a colour by a few 1/255 at
// a few pixels. Anything skipped wrongly (a whole brick of a body) changes far more.
constexpr int kPixelThreshold = 8;
constexpr double kMaxFailingFraction = 0.005;
constexpr double kMaxMeanDelta = 0.3;

struct Case {
    std::string scene;
    std::string dataset;
};

// What ctest lists and gtest reports as the parameter (instead of the struct's bytes).
void PrintTo(const Case& c, std::ostream* out) { *out << c.scene << " on " << c.dataset; }

class SkippingEquivalence : public ::testing::TestWithParam<Case> {};

TEST_P(SkippingEquivalence, OptimisedAndNaiveRaycastersGiveTheSameImage) {
    const Case& c = GetParam();
    // The hurricane-sized and sonar datasets of the benchmark arrive with their own features.
    if (!std::filesystem::exists(kSourceDir / "data" / c.dataset / "series.json"))
        GTEST_SKIP() << "dataset " << c.dataset << " is not there";
    Scene scene = loadScene(kSourceDir / "data/scenes" / (c.scene + ".json"));
    const Series& series = loadSeriesOnce(kSourceDir / "data" / c.dataset / "series.json");
    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    const View view = resolveView(scene.camera, series.worldBounds(), kSize, kSize);
    FrameOptions options;
    options.size = {kSize, kSize};
    renderer.draw(scene, view, options);
    const Image optimised = renderer.readFrame();
    options.naive = true;
    renderer.draw(scene, view, options);
    const Image naive = renderer.readFrame();

    const ImageDifference difference = compareImages(optimised, naive, kPixelThreshold);
    const bool same = difference.failingFraction <= kMaxFailingFraction && difference.meanDelta <= kMaxMeanDelta;
    if (!same) {
        std::filesystem::create_directories(kOutputDir);
        const std::string name = c.scene + "." + c.dataset;
        writeImage(optimised, kOutputDir / (name + ".optimised.png"));
        writeImage(naive, kOutputDir / (name + ".naive.png"));
        writeImage(differenceImage(optimised, naive, 8.0f), kOutputDir / (name + ".difference.png"));
    }
    std::cout << "  " << c.scene << " on " << c.dataset << ": " << describe(difference) << "\n";
    EXPECT_TRUE(same) << c.scene << " on " << c.dataset << ": " << describe(difference);
}

std::vector<Case> benchmarkCases() {
    std::vector<Case> cases;
    // The datasets of `tstyles bench` (src/cli/bench_datasets.cpp).
    for (const char* dataset : {"superellipsoid", "superellipsoid-aligned"})
        for (const char* scene : {"figure4-temporal-mip", "figure4-temporal-average", "figure4-max-density-change",
                                  "figure1-styled-focus-step3", "figure4-styled-max-density-change"})
            cases.push_back({scene, dataset});
    // The hurricane's own scenes, which the benchmark measures it with (missing values, uneven levels).
    for (const char* scene : {"figure5-focus-step5", "figure6-left-max-density-change"})
        cases.push_back({scene, "hurricane"});
    // The sonar survey with its own scenes (the Figure 4 cameras stand inside its fans).
    for (const char* scene : {"figure6-centre-index-tstf", "figure6-right-max-density-change"})
        cases.push_back({scene, "sonar"});
    return cases;
}

INSTANTIATE_TEST_SUITE_P(BenchmarkScenes, SkippingEquivalence, ::testing::ValuesIn(benchmarkCases()),
                         [](const auto& parameter) {
                             std::string name = parameter.param.scene + "_on_" + parameter.param.dataset;
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

}  // namespace
}  // namespace tstyles::testing
