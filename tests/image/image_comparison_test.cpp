// Image comparison on known pairs: identical, one pixel changed by a known amount, a uniform
// offset, a shifted edge (SSIM sees it where the mean hardly does), and SSIM's closed form.
#include <cmath>

#include <gtest/gtest.h>

#include "tstyles/image/image_comparison.h"

namespace {

using namespace tstyles;

Image flat(int width, int height, glm::vec4 colour) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.set(x, y, colour);
    return image;
}

// Left half dark, right half bright, the edge at column `edge`.
Image edgeAt(int edge) {
    Image image(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) image.set(x, y, glm::vec4(glm::vec3(x < edge ? 0.1f : 0.9f), 1.0f));
    return image;
}

TEST(ImageComparison, IdenticalImagesDifferInNothing) {
    const Image image = edgeAt(30);
    const ImageDifference difference = compareImages(image, image, 1);
    EXPECT_EQ(difference.maxDelta, 0);
    EXPECT_EQ(difference.meanDelta, 0.0);
    EXPECT_EQ(difference.failingFraction, 0.0);
    EXPECT_EQ(difference.ssim, 1.0);
    EXPECT_TRUE(difference.worstPixels.empty());
    EXPECT_TRUE(thresholdsExceeded(difference, ComparisonThresholds{}).empty());
    EXPECT_TRUE(within(difference, ComparisonThresholds{}));
}

TEST(ImageComparison, OnePixelChangedByAKnownAmount) {
    const Image expected = flat(10, 10, {0.2f, 0.4f, 0.6f, 1.0f});
    Image actual = expected;
    actual.set(3, 7, {0.2f, 0.4f + 7.0f / 255.0f, 0.6f, 1.0f});
    const ImageDifference difference = compareImages(actual, expected, 1);
    EXPECT_EQ(difference.maxDelta, 7);
    EXPECT_EQ(difference.maxChannelDelta, (std::array<int, 4>{0, 7, 0, 0}));
    EXPECT_DOUBLE_EQ(difference.failingFraction, 0.01);  // 1 of 100 pixels
    EXPECT_DOUBLE_EQ(difference.meanDelta, 7.0 / 400.0);
    ASSERT_EQ(difference.worstPixels.size(), 1u);
    EXPECT_EQ(difference.worstPixels[0].position, glm::ivec2(3, 7));
    EXPECT_EQ(difference.worstPixels[0].delta, 7);
    EXPECT_EQ(difference.worstPixels[0].expected, expected.at(3, 7));
    EXPECT_EQ(difference.worstPixels[0].actual, actual.at(3, 7));
    EXPECT_FALSE(within(difference, ComparisonThresholds{}));
    const auto exceeded = thresholdsExceeded(difference, ComparisonThresholds{});
    ASSERT_EQ(exceeded.size(), 2u);  // max delta and failing share; the mean (0.0175) and SSIM are within
    EXPECT_EQ(exceeded[0], "max delta 7/255 > 2/255");
}

TEST(ImageComparison, AUniformOffsetGivesItsMeanAndSsimInClosedForm) {
    const Image expected = flat(32, 32, {0.4f, 0.4f, 0.4f, 1.0f});
    const Image actual = flat(32, 32, {0.4f + 3.0f / 255.0f, 0.4f + 3.0f / 255.0f, 0.4f + 3.0f / 255.0f, 1.0f});
    const ImageDifference difference = compareImages(actual, expected, 1);
    EXPECT_EQ(difference.maxDelta, 3);
    EXPECT_DOUBLE_EQ(difference.meanDelta, 3.0 * 3.0 / 4.0);  // RGB differ by 3, alpha by 0
    EXPECT_DOUBLE_EQ(difference.failingFraction, 1.0);
    // Flat images: no variance, so SSIM is the luminance term (2 mx my + C1) / (mx^2 + my^2 + C1).
    const double mx = 255.0 * (0.4f + 3.0f / 255.0f);
    const double my = 255.0 * 0.4f;
    const double c1 = (0.01 * 255.0) * (0.01 * 255.0);
    EXPECT_NEAR(difference.ssim, (2.0 * mx * my + c1) / (mx * mx + my * my + c1), 1e-9);
}

TEST(ImageComparison, WorstPixelsAreTheFiveLargestLargestFirst) {
    const Image expected = flat(8, 8, {0.0f, 0.0f, 0.0f, 1.0f});
    Image actual = expected;
    for (int i = 1; i <= 7; ++i) actual.set(i, i, {float(i) / 255.0f, 0.0f, 0.0f, 1.0f});  // delta i at (i, i)
    const ImageDifference difference = compareImages(actual, expected, 1);
    ASSERT_EQ(difference.worstPixels.size(), 5u);
    for (int rank = 0; rank < 5; ++rank) {
        EXPECT_EQ(difference.worstPixels[std::size_t(rank)].delta, 7 - rank);
        EXPECT_EQ(difference.worstPixels[std::size_t(rank)].position, glm::ivec2(7 - rank));
    }
}

TEST(ImageComparison, AShiftedEdgeIsCaughtBySsimWhileTheMeanStaysSmall) {
    const ImageDifference difference = compareImages(edgeAt(31), edgeAt(30), 1);
    EXPECT_LT(difference.meanDelta, 4.0);  // one column of 64 changed
    EXPECT_LT(difference.ssim, 0.99);
    bool ssimNamed = false;
    for (const std::string& line : thresholdsExceeded(difference, ComparisonThresholds{}))
        ssimNamed = ssimNamed || line.rfind("SSIM ", 0) == 0;
    EXPECT_TRUE(ssimNamed);
}

TEST(ImageComparison, PicturesOfTheDifferenceHaveTheirShapes) {
    const Image expected = edgeAt(30);
    const Image actual = edgeAt(31);
    const Image heat = differenceHeatMap(actual, expected, 8);
    EXPECT_EQ(heat.at(0, 0), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));  // unchanged: black
    EXPECT_EQ(heat.at(30, 0), glm::vec4(1.0f));                   // far beyond full scale: white
    const Image combined = sideBySide(expected, actual, heat);
    EXPECT_EQ(combined.width, 3 * 64 + 8);
    EXPECT_EQ(combined.height, 64);
    EXPECT_THROW(compareImages(flat(2, 2, glm::vec4(0.0f)), flat(3, 2, glm::vec4(0.0f)), 1), std::invalid_argument);
}

}  // namespace
