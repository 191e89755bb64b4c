// --precision picks the density atlas' storage: R8, R16 or R32F (RG8, RG16, RG32F with missing
// values). The three give the same image within the quantisation of 8 bits, and take the texture
// memory their texel size says.
#include <algorithm>
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/render/gpu_series.h"
#include "tstyles/render/packed_aligned_atlas.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 64;
const glm::dvec2 kCentre(0.35, 0.35);
constexpr double kViewHeight = 1.0;

// A density ramp along x (0 to 1 over the box), optionally without data where x < 2.
Series rampSeries(DensityPrecision precision, bool withMissing) {
    BoxSpec box = constantBox({0, 0, 0}, 0.0f);
    box.density = [withMissing](glm::ivec3 voxel) {
        if (withMissing && voxel.x < 2) return missingDensity();
        return float(voxel.x) / 7.0f + 0.01f * float(voxel.y);
    };
    Series series = makeSeries({box, box});
    series.precision = precision;
    return series;
}

Scene rampScene() {
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 0.05}, {1.0, 0.6}};
    scene.stf.curve.color = {{0.0, {0, 0, 1}}, {1.0, {1, 0.5, 0}}};
    scene.compositor = compositorNamed("temporal-average");
    scene.finalMode = FinalMode::Stf;
    return scene;
}

float largestDifference(const Image& a, const Image& b) {
    float largest = 0.0f;
    for (std::size_t index = 0; index < a.rgba.size(); ++index)
        largest = std::max(largest, std::abs(a.rgba[index] - b.rgba[index]));
    return largest;
}

float largestValue(const Image& image) {
    return *std::max_element(image.rgba.begin(), image.rgba.end());
}

// 16 bits quantise a density by at most 0.5 / 65535 and 8 bits by 0.5 / 255 (0.002): through an
// STF whose opacity and colour change by at most 1 per unit density, over a slab of 7 reference
// lengths, a channel moves by at most about 7 x 0.002 (0.014); the tolerances are these bounds.
constexpr float k16BitTolerance = 2e-3f;
constexpr float k8BitTolerance = 1.5e-2f;

void expectSameImages(bool withMissing) {
    const Scene scene = rampScene();
    const Image full = renderSeries(rampSeries(DensityPrecision::Bits32, withMissing), scene);
    const Image half = renderSeries(rampSeries(DensityPrecision::Bits16, withMissing), scene);
    const Image byte = renderSeries(rampSeries(DensityPrecision::Bits8, withMissing), scene);
    ASSERT_GT(largestValue(full), 0.1f) << "the ramp must show";
    const float halfDifference = largestDifference(full, half);
    const float byteDifference = largestDifference(full, byte);
    std::cout << "largest channel difference to R32F" << (withMissing ? " (missing values)" : "")
              << ": 16-bit " << halfDifference << ", 8-bit " << byteDifference << "\n";
    // The storage really changed: the ramp's densities are not all multiples of 1/255.
    EXPECT_GT(byteDifference, 0.0f);
    EXPECT_LE(halfDifference, k16BitTolerance);
    EXPECT_LE(byteDifference, k8BitTolerance);
}

TEST(DensityPrecision, EightSixteenAndThirtyTwoBitsGiveTheSameImage) {
    expectSameImages(false);
}

TEST(DensityPrecision, WithMissingValuesTooTheRgPairsGiveTheSameImage) {
    expectSameImages(true);
}

TEST(DensityPrecision, TextureBytesFollowTheTexelSize) {
    testRenderer();  // makes the context current
    for (const bool withMissing : {false, true}) {
        const GpuSeries byte(rampSeries(DensityPrecision::Bits8, withMissing));
        const GpuSeries half(rampSeries(DensityPrecision::Bits16, withMissing));
        const GpuSeries full(rampSeries(DensityPrecision::Bits32, withMissing));
        EXPECT_EQ(byte.precision(), DensityPrecision::Bits8);
        EXPECT_EQ(full.precision(), DensityPrecision::Bits32);
        EXPECT_EQ(byte.hasMissingValues(), withMissing);
        const std::size_t texels = byte.layout().texelCount();
        ASSERT_EQ(half.layout().texelCount(), texels);
        const std::size_t channels = withMissing ? 2 : 1;
        // Everything but the density atlas is the same; it takes 1, 2 or 4 bytes per channel. A
        // 16-bit aligned series also gets the packed atlas (four time-steps a texel) next to it.
        const auto withoutPacked = [](const GpuSeries& series) {
            return series.textureBytes() - (series.packedAtlas() ? series.packedAtlas()->textureBytes() : 0);
        };
        EXPECT_EQ(byte.packedAtlas(), nullptr);
        EXPECT_EQ(full.packedAtlas(), nullptr);
        EXPECT_EQ(withoutPacked(half) - withoutPacked(byte), texels * channels);
        EXPECT_EQ(withoutPacked(full) - withoutPacked(byte), 3 * texels * channels);
        std::cout << "texture bytes" << (withMissing ? " (missing values)" : "") << " for " << texels
                  << " atlas texels: 8-bit " << byte.textureBytes() << ", 16-bit " << half.textureBytes()
                  << ", 32-bit " << full.textureBytes() << "\n";
    }
}

}  // namespace
}  // namespace tstyles::testing
