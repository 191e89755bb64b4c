// Speed-ups must not change images: each benchmark scene rendered by the optimised raycaster
// (per-ray time-step lists, gap jumps, empty-space skipping) and by the naive one (every time-step
// tested at every sample, nothing skipped) gives the same picture.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bundled_scene_comparison.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 160;
// Optimised against naive: samples after a jump between the sonar's pings may sit elsewhere
// along the ray (docs/performance.md), which moves a few pixels of the fish and the seabed.
// Measured at 160x160 on llvmpipe (29 November): the sonar's Figure 6 right at most 33/255, 0.047 %
// of the pixels beyond 8/255, mean 0.0061/255; every other scene at most 1/255, mean 0.0037/255.
// A pixel fails beyond 8/255; at most 0.1 % may (twice the sonar's), mean at most 0.015/255
// (2.5 times). A brick skipped wrongly changes a whole body, far more.
constexpr SameImageTolerance kSkipping{8, 0.001, 0.015};
// The empty-brick test and the per-ray caches on and off change no sample: measured at most
// 1/255 (rounding of the voxel-ray arithmetic), no pixel beyond 2/255, mean at most 0.0034/255 (the
// hurricane). None may fail beyond 2/255, mean at most 0.01/255 (three times).
constexpr SameImageTolerance kSameSamples{2, 0.0, 0.01};

// The picture with a switch of FrameOptions forced on and forced off (`what`: the switch, for
// messages).
void expectSameImageEitherWay(const BundledScene& bundled, std::optional<bool> FrameOptions::*option,
                              const std::string& what) {
    FrameOptions on;
    on.*option = true;
    FrameOptions off;
    off.*option = false;
    const std::string without = "no " + what;
    expectSameImage(bundled, kSize, {what.c_str(), on}, {without.c_str(), off}, kSameSamples);
}

class SkippingEquivalence : public ::testing::TestWithParam<BundledScene> {};

TEST_P(SkippingEquivalence, OptimisedAndNaiveRaycastersGiveTheSameImage) {
    const BundledScene& bundled = GetParam();
    // The hurricane-sized and sonar datasets of the benchmark arrive with their own features.
    if (!std::filesystem::exists(manifestOf(bundled))) GTEST_SKIP() << "dataset " << bundled.dataset << " is not there";
    FrameOptions naive;
    naive.naive = true;
    expectSameImage(bundled, kSize, {"optimised", FrameOptions{}}, {"naive", naive}, kSkipping);
}

std::vector<BundledScene> bundledSceneCases() {
    std::vector<BundledScene> cases;
    // The datasets of `tstyles bench` (src/cli/bench/bench_datasets.cpp).
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
    // Every other bundled scene (data/scenes) on its own dataset.
    for (const char* scene : {"figure1-focus-step3", "figure1-focus-step6", "figure1-styled-focus-step6",
                               "figure4-styled-temporal-average", "figure4-styled-temporal-mip"})
        cases.push_back({scene, "superellipsoid"});
    for (const char* scene : {"figure5-focus-step3", "figure5-focus-step8", "compositors-hurricane-index",
                              "compositors-hurricane-signed", "compositors-hurricane-spread"})
        cases.push_back({scene, "hurricane"});
    cases.push_back({"warped-box-styled", "warped-box"});
    return cases;
}

INSTANTIATE_TEST_SUITE_P(BenchmarkScenes, SkippingEquivalence, ::testing::ValuesIn(bundledSceneCases()),
                         [](const auto& parameter) { return testNameOf(parameter.param); });

// The per-sample empty-brick test is compiled in only where the STF leaves enough bricks empty
// (skipsEmptyBricks): with it forced on and off the optimised raycaster gives the same picture, on
// a series where it skips much (the super-ellipsoid, the hurricane's packed atlas) and on the
// sonar, where no brick is empty and it is left out by default.
class EmptyBrickTestEquivalence : public ::testing::TestWithParam<BundledScene> {};

TEST_P(EmptyBrickTestEquivalence, WithAndWithoutTheTestGiveTheSameImage) {
    const BundledScene& bundled = GetParam();
    if (!std::filesystem::exists(manifestOf(bundled))) GTEST_SKIP() << "dataset " << bundled.dataset << " is not there";
    expectSameImageEitherWay(bundled, &FrameOptions::emptyBrickTest, "empty-brick test");
}

INSTANTIATE_TEST_SUITE_P(BenchmarkScenes, EmptyBrickTestEquivalence,
                         ::testing::Values(BundledScene{"figure4-temporal-mip", "superellipsoid"},
                                           BundledScene{"figure1-styled-focus-step3", "superellipsoid-aligned"},
                                           BundledScene{"figure5-focus-step5", "hurricane"},
                                           BundledScene{"figure6-centre-index-tstf", "sonar"}),
                         [](const auto& parameter) { return testNameOf(parameter.param); });

// The per-ray caches (voxel rays, the temporal average's deferred styling) are on by default on a
// CPU rasterizer and off on a GPU: both give the same picture, on every kind of walk and grid (ray
// list on boxes, on the hurricane's uneven levels and on the sonar's beam fans, the packed walk of
// the aligned series, the curvilinear warped box) and for the average styled both ways, and where
// its styles show inside the masks only, so that some of a sample's time-steps are styled as the
// walk meets them and the others in the finish (the sonar's index TSTF). Without
// the caches a sample's voxel position is one matrix product instead of origin + t * direction:
// float rounding alone tells them apart.
class PerRayCachesEquivalence : public ::testing::TestWithParam<BundledScene> {};

TEST_P(PerRayCachesEquivalence, WithAndWithoutTheCachesGiveTheSameImage) {
    const BundledScene& bundled = GetParam();
    if (!std::filesystem::exists(manifestOf(bundled))) GTEST_SKIP() << "dataset " << bundled.dataset << " is not there";
    expectSameImageEitherWay(bundled, &FrameOptions::perRayCaches, "per-ray caches");
}

INSTANTIATE_TEST_SUITE_P(BenchmarkScenes, PerRayCachesEquivalence,
                         ::testing::Values(BundledScene{"figure4-temporal-average", "superellipsoid"},
                                           BundledScene{"figure4-styled-temporal-average", "superellipsoid"},
                                           BundledScene{"figure4-styled-temporal-average", "superellipsoid-aligned"},
                                           BundledScene{"figure4-max-density-change", "superellipsoid-aligned"},
                                           BundledScene{"figure5-focus-step5", "hurricane"},
                                           BundledScene{"figure6-centre-index-tstf", "sonar"},
                                           BundledScene{"figure6-right-max-density-change", "sonar"},
                                           BundledScene{"figure6-centre-index-tstf", "sonar", "temporal-average"},
                                           BundledScene{"warped-box-styled", "warped-box"}),
                         [](const auto& parameter) { return testNameOf(parameter.param); });

}  // namespace
}  // namespace tstyles::testing
