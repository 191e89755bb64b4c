// The GPU memory budget: the estimate is what the upload allocates, and a series over the budget
// renders with the stated strategy, its image compared with the unlimited render.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/coarser_series.h"
#include "tstyles/image/image_comparison.h"
#include "tstyles/image/image_io.h"
#include "tstyles/render/gpu_memory_budget.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 64;
const glm::dvec2 kCentre(0.35, 0.35);
constexpr double kViewHeight = 1.0;
constexpr std::uint64_t kUnlimited = std::uint64_t(1) << 40;

GpuMemoryLimits limitsOf(std::uint64_t budget) {
    GpuMemoryLimits limits;
    limits.budgetBytes = budget;
    return limits;
}

// Four time-steps on one 8^3 grid (packable) whose density is linear in position: trilinear
// resampling reproduces a linear field exactly, so a coarser upload changes no sampled density.
Series linearAlignedSeries() {
    BoxSpec box = constantBox({0, 0, 0}, 0.0f);
    std::vector<BoxSpec> boxes;
    for (int step = 0; step < 4; ++step) {
        box.density = [step](glm::ivec3 voxel) {
            return 0.1f + 0.05f * float(step) + 0.06f * float(voxel.x) + 0.03f * float(voxel.y) + 0.01f * float(voxel.z);
        };
        boxes.push_back(box);
    }
    return makeSeries(boxes);
}

Scene linearScene() {
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 0.05}, {1.0, 0.6}};
    scene.stf.curve.color = {{0.0, {0, 0, 1}}, {1.0, {1, 0.5, 0}}};
    scene.compositor = compositorNamed("temporal-average");
    scene.finalMode = FinalMode::Stf;
    return scene;
}

Image renderWithin(const Series& series, const Scene& scene, std::uint64_t budget, GpuResidency& residency) {
    residency = testRenderer().setSeries(series, limitsOf(budget));
    return drawWithCurrentSeries(scene, series.worldBounds(), {});
}

float largestDifference(const Image& a, const Image& b) {
    float largest = 0.0f;
    for (std::size_t index = 0; index < a.rgba.size(); ++index)
        largest = std::max(largest, std::abs(a.rgba[index] - b.rgba[index]));
    return largest;
}

float largestValue(const Image& image) { return *std::max_element(image.rgba.begin(), image.rgba.end()); }

// Series of every storage kind the plan knows: the estimate must be what the driver allocated.
std::vector<std::pair<const char*, Series>> seriesKinds() {
    std::vector<std::pair<const char*, Series>> kinds;
    BoxSpec first = constantBox({0, 0, 0}, 0.5f);
    BoxSpec second = constantBox({0.3, 0, 0}, 0.7f);
    second.dims = {12, 6, 9};
    kinds.emplace_back("two placements, 16-bit", makeSeries({first, second}));
    for (DensityPrecision precision : {DensityPrecision::Bits8, DensityPrecision::Bits32}) {
        Series series = makeSeries({first, second});
        series.precision = precision;
        kinds.emplace_back(precision == DensityPrecision::Bits8 ? "8-bit" : "32-bit", std::move(series));
    }
    BoxSpec missing = first;
    missing.density = [](glm::ivec3 voxel) { return voxel.x < 2 ? missingDensity() : 0.4f; };
    kinds.emplace_back("missing values", makeSeries({missing, second}));
    BoxSpec masked = second;
    masked.mask = [](glm::ivec3 voxel) { return voxel.y > 2; };
    kinds.emplace_back("masks", makeSeries({first, masked}));
    kinds.emplace_back("aligned (packed atlas)", linearAlignedSeries());
    kinds.emplace_back("aligned, shared missing values", makeSeries({missing, missing, missing}));
    BoxSpec otherMissing = missing;
    otherMissing.density = [](glm::ivec3 voxel) { return voxel.y < 3 ? missingDensity() : 0.4f; };
    kinds.emplace_back("aligned, missing values per group", makeSeries({missing, otherMissing, missing, missing, missing}));
    return kinds;
}

TEST(GpuMemoryBudget, EstimateEqualsTheBytesAllocated) {
    for (const auto& [name, series] : seriesKinds()) {
        const GpuResidency planned = fitToGpuMemory(series, limitsOf(kUnlimited));
        testRenderer().setSeries(series, limitsOf(kUnlimited));
        EXPECT_EQ(planned.chosenBytes, testRenderer().seriesTextureBytes()) << name;
        EXPECT_EQ(planned.fullBytes, planned.chosenBytes) << name;
        // Under half the budget it needs, the reduced series' estimate holds as well.
        const GpuResidency reduced = fitToGpuMemory(series, limitsOf(planned.chosenBytes / 2));
        EXPECT_TRUE(reduced.changed()) << name;
        const GpuResidency uploaded = testRenderer().setSeries(series, limitsOf(planned.chosenBytes / 2));
        EXPECT_LE(uploaded.chosenBytes, planned.chosenBytes / 2) << name;
        EXPECT_EQ(reduced.chosenBytes, uploaded.chosenBytes) << name;
    }
}

// Without the packed atlas the general path draws the same image (packed_aligned_test.cpp).
TEST(GpuMemoryBudget, LeavingOutThePackedAtlasKeepsTheImage) {
    const Series series = linearAlignedSeries();
    const Scene scene = linearScene();
    GpuResidency full, reduced;
    const Image unlimited = renderWithin(series, scene, kUnlimited, full);
    ASSERT_TRUE(full.storage.packedAtlas);
    const Image within = renderWithin(series, scene, *full.fullBytes - 1, reduced);
    EXPECT_FALSE(reduced.storage.packedAtlas);
    EXPECT_EQ(reduced.scale, 1.0);
    EXPECT_EQ(reduced.storage.precision, DensityPrecision::Bits16);
    ASSERT_GT(largestValue(unlimited), 0.1f);
    // Both paths filter the same 16-bit texels with the same weights; only float rounding differs.
    EXPECT_LE(largestDifference(unlimited, within), 1e-5f);
}

// A linear field survives a coarser grid exactly (trilinear resampling and trilinear filtering
// reproduce it), and the coarser upload keeps the full series' step and opacity reference: what
// is left is the 16-bit quantisation of both uploads, at most 0.5 / 65535 per density each; through
// an STF that changes by at most 1 per unit density over 7 reference lengths a channel moves by
// at most 7 x 1 / 65535 = 1.1e-4. The tolerance is twice that.
TEST(GpuMemoryBudget, CoarserLinearFieldMatchesTheUnlimitedImage) {
    const Series series = linearAlignedSeries();
    const Scene scene = linearScene();
    GpuResidency full, reduced;
    const Image unlimited = renderWithin(series, scene, kUnlimited, full);
    const Image within = renderWithin(series, scene, *full.fullBytes / 6, reduced);
    EXPECT_GT(reduced.scale, 1.0);
    EXPECT_LT(reduced.chosenDims.x, 8);
    EXPECT_LE(reduced.chosenBytes, *full.fullBytes / 6);
    ASSERT_GT(largestValue(unlimited), 0.1f);
    EXPECT_LE(largestDifference(unlimited, within), 2.2e-4f);
}

// Values k / 255 are stored exactly at 8 bits, so the budget takes 8 bits before a coarser grid.
// llvmpipe filters 8-bit textures in 8-bit arithmetic, rounding the filtered density to 1 / 255
// (docs/large-series.md): 0.5 / 255 per sample, and over 7 reference lengths through an STF of
// slope at most 1 a channel moves by at most 7 x 0.002 = 0.014, density_precision_test's bound.
TEST(GpuMemoryBudget, ExactEightBitValuesAreStoredAtEightBits) {
    BoxSpec box = constantBox({0, 0, 0}, 0.0f);
    box.density = [](glm::ivec3 voxel) { return float(20 * voxel.x + 3 * voxel.y + voxel.z) / 255.0f; };
    BoxSpec shifted = box;
    shifted.origin = {0.05, 0.0, 0.0};  // two placements: no packed atlas to leave out first
    const Series series = makeSeries({box, shifted});
    const Scene scene = linearScene();
    GpuResidency full, reduced;
    const Image unlimited = renderWithin(series, scene, kUnlimited, full);
    const Image within = renderWithin(series, scene, *full.fullBytes - 1, reduced);
    EXPECT_EQ(reduced.storage.precision, DensityPrecision::Bits8);
    EXPECT_EQ(reduced.scale, 1.0);
    ASSERT_GT(largestValue(unlimited), 0.1f);
    EXPECT_LE(largestDifference(unlimited, within), 1.5e-2f);
    // A value between two 8-bit levels keeps the series at 16 bits: it goes coarser instead.
    Series offLevel = series;
    offLevel.steps[1].density[5] += 0.5f / 255.0f;
    EXPECT_GT(fitToGpuMemory(offLevel, limitsOf(*full.fullBytes - 1)).scale, 1.0);
}

// The bundled hurricane (10 aligned time-steps, uneven pressure levels, missing values) in its
// automatic scene, within a budget that takes it to a coarser grid without the packed atlas: the
// general path with uneven-axis lookups at every time-step, where llvmpipe's limit of 65535 loop
// passes per invocation once cut 735 of these rays short, leaving a blocky patch 85/255 off: two
// while loops of the node lookup ran for every time-step at every sample (docs/architecture.md,
// "Limits: samples per ray on llvmpipe").
TEST(GpuMemoryBudget, CoarserHurricaneIsNotCutShortAndKeepsItsImage) {
    const std::filesystem::path manifest = std::filesystem::path(TSTYLES_SOURCE_DIR) / "data/hurricane/series.json";
    const Series& read = loadSeriesOnce(manifest);
    const SceneOnSeries fitted = fitSceneToSeries(automaticScene(read, manifest).scene, read);
    Scene scene = fitted.scene;
    scene.width = scene.height = 192;
    // The oblique three-quarter view the bounds below were measured in; the automatic camera now
    // looks at the hurricane, a slab, from above, where the coarser grid's 21 levels for 25 move
    // single pixels further (max 96/255, mean 0.33/255, SSIM 0.9973 measured).
    scene.camera.pose = OrbitCamera{};
    const Series& series = fitted.series;

    testRenderer().setSeries(series, limitsOf(kUnlimited));
    const Image full = drawWithCurrentSeries(scene, fitted.framed, {});
    ASSERT_EQ(testRenderer().lastCutShortRays(), 0u);

    // 9 MiB of the 24.6 MiB it needs: resolution 1/1.18 per axis (125x125x25 -> 105x105x21).
    const GpuResidency reduced = testRenderer().setSeries(series, limitsOf(9u << 20));
    ASSERT_GT(reduced.scale, 1.0);
    ASSERT_FALSE(reduced.storage.packedAtlas);
    const Image within = drawWithCurrentSeries(scene, fitted.framed, {});
    EXPECT_EQ(testRenderer().lastCutShortRays(), 0u);

    // The same coarser grid through the packed path, with the full series' step and opacity
    // reference as the budget keeps them: packed and general path agree to rounding
    // (packed_aligned_test.cpp's tolerance), so the budget's image is the coarser grid's, whole.
    const Series coarse = coarserSeries(series, reduced.scale);
    testRenderer().setSeries(coarse, WholeSeries{series.finestSpacing(), series.worldBounds()});
    const Image coarsePacked = drawWithCurrentSeries(scene, fitted.framed, {});
    const ImageDifference path = compareImages(within, coarsePacked, 2);
    // What the coarser grid cannot hold: level sets of the clouds move by up to a coarse voxel, so
    // single pixels on their edges differ, but the picture does not: measured max 23/255, mean
    // 0.16/255, SSIM 0.9984 here (31/255, 0.20/255, 0.9978 on 6 December 2026) (35/255, 0.16/255, 0.9978 at 512 x 512). The bounds leave room for
    // another driver's filtering; the cut-short patch broke three of them (max 85/255, and 0.62 %
    // failing pixels against the coarser grid's own image).
    const ImageDifference loss = compareImages(within, full, 2);
    const bool failed = path.failingFraction > 0.001 || path.meanDelta > 0.05 || loss.meanDelta > 0.5 ||
                        loss.ssim < 0.99 || loss.maxDelta > 48;
    if (failed) {
        const std::filesystem::path output = TSTYLES_TEST_OUTPUT_DIR;
        std::filesystem::create_directories(output);
        writeImage(full, output / "hurricane-budget.full.png");
        writeImage(within, output / "hurricane-budget.within.png");
        writeImage(coarsePacked, output / "hurricane-budget.coarse-packed.png");
        writeImage(differenceImage(within, full, 8.0f), output / "hurricane-budget.within-full.difference.png");
    }
    EXPECT_LE(path.failingFraction, 0.001) << describe(path);
    EXPECT_LE(path.meanDelta, 0.05) << describe(path);
    EXPECT_LE(loss.meanDelta, 0.5) << describe(loss);
    EXPECT_GE(loss.ssim, 0.99) << describe(loss);
    EXPECT_LE(loss.maxDelta, 48) << describe(loss);
    std::cout << "  within 9 MiB against the coarser grid's packed image: " << describe(path)
              << "\n  against the unlimited image: " << describe(loss) << "\n";
}

TEST(GpuMemoryBudget, LargestTextureLimitIsRespected) {
    const Series series = linearAlignedSeries();
    GpuMemoryLimits limits = limitsOf(kUnlimited);
    limits.largestTextureBytes = 1000;
    const GpuResidency residency = fitToGpuMemory(series, limits);
    EXPECT_GT(residency.scale, 1.0);
    const SeriesTexturePlan plan =
        planSeriesTextures(shapeOf(coarserSeries(series, residency.scale)), residency.storage, limits.maxTextureSize);
    EXPECT_LE(largestBytes(plan.textures()), 1000u);
}

TEST(GpuMemoryBudget, SeriesThatCannotBeCoarsenedIsRefusedWithTheOption) {
    const Series& structured = loadSeriesOnce(std::filesystem::path(TSTYLES_SOURCE_DIR) / "data/warped-box/series.json");
    try {
        fitToGpuMemory(structured, limitsOf(64));
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("--max-gpu-memory"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("only rectilinear grids"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace tstyles::testing
