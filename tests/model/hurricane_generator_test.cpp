// The synthetic hurricane generator (tools/hurricane): an eye at the track position, a track that
// curves from west-northwest to north, land as missing values, uneven increasing levels, and the
// same bytes on every run.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "hurricane/hurricane_model.h"
#include "hurricane/hurricane_series.h"
#include "test_dataset.h"
#include "tstyles/data/manifest.h"

namespace {

using hurricane::kLandMarker;

// The generator's default series (10 x 125x125x25), built once for all tests here.
const tstyles::RawSeries& defaultSeries() {
    static const tstyles::RawSeries series = hurricane::buildHurricaneSeries({});
    return series;
}

std::uint8_t valueAt(const tstyles::RawTimeStep& step, int x, int y, int z) {
    const glm::ivec3 dims = step.grid.dims;
    return step.bytes[std::size_t(x) + std::size_t(dims.x) * (std::size_t(y) + std::size_t(dims.y) * std::size_t(z))];
}

std::vector<char> fileBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(HurricaneGenerator, TenTimeStepsOf125x125x25Over48Hours) {
    const auto& series = defaultSeries();
    ASSERT_EQ(series.steps.size(), 10u);
    EXPECT_DOUBLE_EQ(series.steps.front().time, 0.0);
    EXPECT_DOUBLE_EQ(series.steps.back().time, 48.0);
    for (const auto& step : series.steps) {
        EXPECT_EQ(step.grid.dims, glm::ivec3(125, 125, 25));
        EXPECT_EQ(step.bytes.size(), 125u * 125u * 25u);
        // One common grid and placement: the time-steps overlap fully.
        EXPECT_EQ(step.placement, series.steps.front().placement);
    }
}

// At a mid-height level the voxel nearest the storm centre holds less cloud water than every
// voxel within the eye wall's reach, and the eye wall around it is dense.
TEST(HurricaneGenerator, EyeIsALocalMinimumAtTheTrackPosition) {
    const auto& series = defaultSeries();
    const int level = 10;
    for (const auto& step : series.steps) {
        const glm::dvec2 centre = hurricane::stormCentre(step.time);
        const glm::ivec2 eye(glm::round(centre / glm::dvec2(step.grid.spacing)));
        const int eyeValue = valueAt(step, eye.x, eye.y, level);
        const int reach = int(std::ceil(0.2 / step.grid.spacing.x));  // beyond the eye wall
        int wallMaximum = 0;
        for (int dy = -reach; dy <= reach; ++dy)
            for (int dx = -reach; dx <= reach; ++dx) {
                const int value = valueAt(step, eye.x + dx, eye.y + dy, level);
                if (value == int(kLandMarker)) continue;
                EXPECT_LE(eyeValue, value) << "t = " << step.time << " h, offset " << dx << ", " << dy;
                wallMaximum = std::max(wallMaximum, value);
            }
        EXPECT_LT(eyeValue, 10) << "the eye is clear at t = " << step.time << " h";
        EXPECT_GT(wallMaximum, 150) << "the eye wall is dense at t = " << step.time << " h";
    }
}

// Isabel moved west-northwest, then turned north-northwest towards the coast.
TEST(HurricaneGenerator, TrackCurvesFromWestNorthwestToNorth) {
    const glm::dvec2 early = hurricane::stormCentre(6.0) - hurricane::stormCentre(0.0);
    const glm::dvec2 late = hurricane::stormCentre(48.0) - hurricane::stormCentre(42.0);
    EXPECT_LT(early.x, 0.0);
    EXPECT_GT(early.y, 0.0);
    EXPECT_GT(-early.x, 2.0 * early.y) << "heading west-northwest at first";
    EXPECT_GT(late.y, 0.0);
    EXPECT_GT(late.y, 3.0 * std::abs(late.x)) << "heading about north at the end";
    // Still over the sea at the end, near the coast.
    const glm::dvec2 end = hurricane::stormCentre(48.0);
    EXPECT_FALSE(hurricane::isLand(end));
    EXPECT_LT(end.x - hurricane::coastline(end.y), 0.25);
}

TEST(HurricaneGenerator, LandVoxelsAreMissingAndSeaHasData) {
    const auto& series = defaultSeries();
    ASSERT_TRUE(series.missingValue.has_value());
    EXPECT_EQ(*series.missingValue, kLandMarker);
    EXPECT_LT(series.valueRange[1], kLandMarker) << "no data value may look like the marker";
    const auto& step = series.steps[4];
    int landColumns = 0;
    int seaColumns = 0;
    for (int y = 0; y < step.grid.dims.y; ++y)
        for (int x = 0; x < step.grid.dims.x; ++x) {
            const glm::dvec2 ground = glm::dvec2(x, y) * glm::dvec2(step.grid.spacing);
            const bool land = hurricane::isLand(ground);
            (land ? landColumns : seaColumns) += 1;
            EXPECT_EQ(valueAt(step, x, y, 0) == kLandMarker, land) << "column " << x << ", " << y;
            // Above the ground every voxel is air with a value; the top level is air everywhere.
            EXPECT_NE(valueAt(step, x, y, step.grid.dims.z - 1), kLandMarker);
            for (int z = 0; z < step.grid.dims.z; ++z) {
                const bool belowGround = step.grid.axisPositions[2][std::size_t(z)] < hurricane::terrainHeight(ground);
                ASSERT_EQ(valueAt(step, x, y, z) == kLandMarker, belowGround) << x << ", " << y << ", " << z;
            }
        }
    EXPECT_GT(landColumns, 125 * 125 / 10);
    EXPECT_GT(seaColumns, 125 * 125 / 2);
}

TEST(HurricaneGenerator, LevelsAreUnevenAndIncreasing) {
    const auto& grid = defaultSeries().steps.front().grid;
    ASSERT_TRUE(grid.isUneven(2));
    EXPECT_FALSE(grid.isUneven(0));
    EXPECT_FALSE(grid.isUneven(1));
    const std::vector<double>& heights = grid.axisPositions[2];
    EXPECT_EQ(heights, hurricane::levelHeights(25));
    ASSERT_EQ(heights.size(), 25u);
    EXPECT_EQ(heights.front(), 0.0);
    EXPECT_DOUBLE_EQ(heights.back(), hurricane::kTopHeight);
    for (std::size_t k = 2; k < heights.size(); ++k) {
        EXPECT_GT(heights[k - 1], heights[k - 2]);
        EXPECT_GT(heights[k] - heights[k - 1], heights[k - 1] - heights[k - 2]) << "gaps grow upward at " << k;
    }
    // Dense near the surface: the top gap is three times the lowest.
    EXPECT_NEAR((heights[24] - heights[23]) / (heights[1] - heights[0]), 3.0, 1e-9);
}

TEST(HurricaneGenerator, EveryRunWritesTheSameBytes) {
    const tstyles::RawSeries again = hurricane::buildHurricaneSeries({});
    ASSERT_EQ(again.steps.size(), defaultSeries().steps.size());
    for (std::size_t i = 0; i < again.steps.size(); ++i)
        EXPECT_TRUE(again.steps[i].bytes == defaultSeries().steps[i].bytes) << "time-step " << i;

    hurricane::HurricaneSeriesOptions small;
    small.steps = 3;
    const auto first = tstyles_test::freshFolder("hurricane_first");
    const auto second = tstyles_test::freshFolder("hurricane_second");
    tstyles::writeSeries(hurricane::buildHurricaneSeries(small), first);
    tstyles::writeSeries(hurricane::buildHurricaneSeries(small), second);
    for (const char* name : {"series.json", "t00.raw", "t01.raw", "t02.raw"}) {
        EXPECT_FALSE(fileBytes(first / name).empty()) << name;
        EXPECT_EQ(fileBytes(first / name), fileBytes(second / name)) << name;
    }
    // Read back: land is missing (NaN density), the levels are kept.
    const tstyles::Series series = tstyles::loadSeries(first / "series.json");
    ASSERT_EQ(series.size(), 3u);
    EXPECT_DOUBLE_EQ(series.steps[2].time, 48.0);
    EXPECT_TRUE(std::isnan(series.steps[0].density[0])) << "the south-west corner is land";
    EXPECT_EQ(series.steps[0].rectilinear().axisPositions[2], hurricane::levelHeights(25));
    std::filesystem::remove_all(first);
    std::filesystem::remove_all(second);
}

}  // namespace
