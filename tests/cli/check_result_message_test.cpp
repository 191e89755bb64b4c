// CaseResult through the bytes `check --distributed` sends between processes: every field comes
// back exactly (floats bit for bit, images included), and bytes it did not write are an error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "check_result_message.h"

namespace tstyles::cli {
namespace {

Image oddImage() {
    Image image(3, 2);  // not square, not a power of two: rows and columns cannot be swapped unseen
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = float(i) / 3.0f + 0.1f;
    image.rgba[5] = -0.0f;
    image.rgba[6] = std::numeric_limits<float>::quiet_NaN();
    image.rgba[7] = std::numeric_limits<float>::denorm_min();
    return image;
}

void expectSameBits(const Image& actual, const Image& expected) {
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    ASSERT_EQ(actual.rgba.size(), expected.rgba.size());
    EXPECT_EQ(std::memcmp(actual.rgba.data(), expected.rgba.data(), actual.rgba.size() * sizeof(float)), 0);
}

TEST(CheckResultMessage, FailedCaseComesBackExactly) {
    CaseResult sent{"figure1-focus-step6", "data/scenes/figure1-focus-step6.json"};
    sent.outcome = CaseOutcome::Failed;
    ImageDifference difference;
    difference.maxChannelDelta = {223, 17, 0, 1};
    difference.maxDelta = 223;
    difference.meanDelta = 1.0 / 3.0;
    difference.failingFraction = 0.0175629;
    difference.ssim = 0.978309123456789;
    difference.worstPixels = {{{2, 1}, 223, {0.1f, 0.2f, 1.0f / 3.0f, 1.0f}, {0.9f, 0.0f, 0.0f, 0.5f}},
                              {{0, 0}, 17, {0.0f, 0.0f, 0.0f, 0.0f}, {1e-8f, 0.0f, 0.0f, 0.0f}}};
    sent.difference = difference;
    sent.problems = {"max delta 223/255 > 2/255", "SSIM 0.978309 < 0.99"};
    sent.seconds = 0.1 + 0.2;
    sent.expected = oddImage();
    sent.actual = oddImage();
    sent.actual->rgba[0] = 0.75f;

    const CaseResult got = decodeCaseResult(encodeCaseResult(sent));
    EXPECT_EQ(got.name, sent.name);
    EXPECT_EQ(got.scene, sent.scene);
    EXPECT_EQ(got.outcome, sent.outcome);
    EXPECT_EQ(got.problems, sent.problems);
    EXPECT_EQ(got.seconds, sent.seconds);
    ASSERT_TRUE(got.difference);
    EXPECT_EQ(got.difference->maxChannelDelta, difference.maxChannelDelta);
    EXPECT_EQ(got.difference->maxDelta, difference.maxDelta);
    EXPECT_EQ(got.difference->meanDelta, difference.meanDelta);
    EXPECT_EQ(got.difference->failingFraction, difference.failingFraction);
    EXPECT_EQ(got.difference->ssim, difference.ssim);
    ASSERT_EQ(got.difference->worstPixels.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(got.difference->worstPixels[i].position, difference.worstPixels[i].position);
        EXPECT_EQ(got.difference->worstPixels[i].delta, difference.worstPixels[i].delta);
        EXPECT_EQ(got.difference->worstPixels[i].expected, difference.worstPixels[i].expected);
        EXPECT_EQ(got.difference->worstPixels[i].actual, difference.worstPixels[i].actual);
    }
    ASSERT_TRUE(got.expected && got.actual);
    expectSameBits(*got.expected, *sent.expected);
    expectSameBits(*got.actual, *sent.actual);
}

TEST(CheckResultMessage, MissingGoldenHasNoDifferenceNorExpectedImage) {
    CaseResult sent{"average", "scenes/average.json"};
    sent.outcome = CaseOutcome::MissingGolden;
    sent.problems = {"no golden image at golden/average.png"};
    sent.actual = oddImage();
    const CaseResult got = decodeCaseResult(encodeCaseResult(sent));
    EXPECT_EQ(got.outcome, CaseOutcome::MissingGolden);
    EXPECT_FALSE(got.difference);
    EXPECT_FALSE(got.expected);
    ASSERT_TRUE(got.actual);
    expectSameBits(*got.actual, *sent.actual);
}

TEST(CheckResultMessage, BytesItDidNotWriteAreAnError) {
    EXPECT_THROW(decodeCaseResult({0x01, 0x02, 0x03}), std::runtime_error);
    std::vector<std::uint8_t> cut = encodeCaseResult(CaseResult{"a", "a.json"});
    cut.resize(cut.size() / 2);
    EXPECT_THROW(decodeCaseResult(cut), std::runtime_error);
}

}  // namespace
}  // namespace tstyles::cli
