// The numbers behind `tstyles info` against closed forms, and the text it prints.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "tstyles/data/series_summary.h"

namespace {

tstyles::TimeStep boxStep(double time, glm::ivec3 dims, glm::dvec3 origin, bool masked = false) {
    tstyles::TimeStep step;
    step.time = time;
    step.grid = tstyles::RectilinearGrid{dims, glm::dvec3(1.0)};
    step.placement.origin = origin;
    step.sourceType = tstyles::ValueType::UInt8;
    if (masked) step.mask = std::vector<std::uint8_t>(step.rectilinear().voxelCount(), 1);
    return step;
}

// Steps 0 and 1: 2 x 2 x 2 boxes offset by 1 along x (half of each inside the other).
// Step 2: a 1 x 1 x 1 box at (1.5, 1.5, 1.5), one eighth of it inside step 1.
tstyles::Series threeBoxes() {
    tstyles::Series series;
    series.name = "three boxes";
    series.manifestPath = "/data/boxes/series.json";
    series.valueRange = {0.0, 255.0};
    series.steps.push_back(boxStep(0.0, {3, 3, 3}, {0.0, 0.0, 0.0}));
    series.steps.push_back(boxStep(0.5, {3, 3, 3}, {1.0, 0.0, 0.0}));
    series.steps.push_back(boxStep(2.0, {2, 2, 2}, {2.5, 1.5, 1.5}, true));
    return series;
}

TEST(OverlapFraction, SharesOfTheSmallerBoxAreClosedForm) {
    const tstyles::Series series = threeBoxes();
    // Intersection [1,2] x [0,2] x [0,2] = 4 of each box's 8.
    EXPECT_DOUBLE_EQ(tstyles::overlapFraction(series, 0, 1), 0.5);
    EXPECT_DOUBLE_EQ(tstyles::overlapFraction(series, 1, 0), 0.5);
    // Step 2 spans [2.5,3.5] x [1.5,2.5] x [1.5,2.5]; step 1 ends at (3, 2, 2): 0.5^3 of a unit box.
    EXPECT_DOUBLE_EQ(tstyles::overlapFraction(series, 1, 2), 0.125);
    EXPECT_DOUBLE_EQ(tstyles::overlapFraction(series, 0, 2), 0.0);
    EXPECT_DOUBLE_EQ(tstyles::overlapFraction(series, 0, 0), 1.0);
}

TEST(OverlapFraction, RotationEnlargesTheWorldBox) {
    tstyles::Series series;
    series.steps.push_back(boxStep(0.0, {2, 2, 2}, {0.0, 0.0, 0.0}));
    series.steps.push_back(boxStep(1.0, {2, 2, 2}, {0.0, 0.0, 0.0}));
    series.steps[1].placement.rotation = glm::angleAxis(glm::radians(45.0), glm::dvec3(0, 0, 1));
    // The turned unit square's box is [-h, h] x [0, 2h] (h = sqrt(1/2)); the unit box inside it is
    // [0, h] x [0, 1] x [0, 1], so the smaller (unit) box is h inside.
    EXPECT_NEAR(tstyles::overlapFraction(series, 0, 1), std::sqrt(0.5), 1e-12);
}

TEST(SeriesMemory, GpuAndDiskBytesCountDensityAndMasks) {
    tstyles::Series series = threeBoxes();
    series.steps[1].sourceType = tstyles::ValueType::Float32;
    // GPU: 27 * 2 + 27 * 2 + (8 * 2 + 8 mask); disk: 27 uint8 + 27 float32 + (8 uint8 + 8 mask).
    EXPECT_EQ(tstyles::gpuBytes(series), 54u + 54u + 24u);
    EXPECT_EQ(tstyles::diskBytes(series), 27u + 108u + 16u);
}

TEST(SeriesAlignment, OneCommonGridAndPlacementIsFullyAligned) {
    tstyles::Series series;
    series.steps.push_back(boxStep(0.0, {3, 3, 3}, {1.0, 0.0, 0.0}));
    series.steps.push_back(boxStep(1.0, {3, 3, 3}, {1.0, 0.0, 0.0}));
    EXPECT_TRUE(tstyles::isFullyAligned(series));
    EXPECT_NE(tstyles::describeSeries(series).find("fully aligned: one common grid"), std::string::npos);

    series.steps[1].grid = tstyles::RectilinearGrid{{3, 3, 4}, glm::dvec3(1.0)};
    EXPECT_FALSE(tstyles::isFullyAligned(series));
    series.steps[1].grid = series.steps[0].grid;
    series.steps[1].placement.rotation = glm::angleAxis(glm::radians(1.0), glm::dvec3(1, 0, 0));
    EXPECT_FALSE(tstyles::isFullyAligned(series));
    EXPECT_NE(tstyles::describeSeries(series).find("partial overlap"), std::string::npos);
}

TEST(DescribeSeries, MentionsTheSeriesEachTimeStepAndEachOverlap) {
    const std::string text = tstyles::describeSeries(threeBoxes());
    for (const std::string part :
         {"three boxes", "/data/boxes/series.json", "Time-steps: 3", "[0, 255]", "partial overlap",
          "rectilinear 3x3x3", "rectilinear 2x2x2", "(2.5, 1.5, 1.5)", "0 - 1", "50.0 %", "1 - 2", "12.5 %",
          "MiB on disk", "MiB on the GPU"}) {
        EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' missing from:\n" << text;
    }
    // One table row per time-step, each starting with its index and time.
    EXPECT_NE(text.find("\n  0  0 "), std::string::npos) << text;
    EXPECT_NE(text.find("\n  1  0.5 "), std::string::npos) << text;
    EXPECT_NE(text.find("\n  2  2 "), std::string::npos) << text;
}

}  // namespace
