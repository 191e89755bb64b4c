// The bucket lookup of uneven axes (render/uneven_axis_table.h, mirrored by the shaders' nodeIndexIn)
// gives the same fractional node index as the data model's inverse of the axis (data/grid_axes.h),
// on the synthetic hurricane's levels (one cell record per bucket, no loop) and on an axis
// whose gaps span four orders of magnitude (a walk from the bucket's cell, UNEVEN_AXIS_WALK).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/data/grid_axes.h"
#include "tstyles/render/uneven_axis_table.h"

namespace tstyles {
namespace {

Series seriesWithZNodes(const std::vector<double>& nodes) {
    RectilinearGrid grid;
    grid.dims = {2, 2, int(nodes.size())};
    grid.axisPositions[2] = nodes;
    TimeStep step;
    step.grid = grid;
    Series series;
    series.steps.push_back(step);
    return series;
}

// Every position from a bit below the first node to a bit above the last, and every node exactly.
void expectLookupMatchesGridAxes(const std::vector<double>& nodes) {
    const Series series = seriesWithZNodes(nodes);
    const RectilinearGrid& grid = series.steps[0].rectilinear();
    const UnevenAxisTable table = buildUnevenAxisTable(series);
    ASSERT_EQ(table.steps.size(), 1u);
    const int count = int(nodes.size());
    ASSERT_GE(table.steps[0].firstNode.z, 0);
    std::vector<double> positions = nodes;
    for (int i = -100; i <= 10100; ++i) positions.push_back(nodes.back() * i / 10000.0);
    for (const double position : positions) {
        const double expected = std::clamp(fractionalIndex(grid, 2, position), 0.0, double(count - 1));
        const float found = lookUpNodeIndex(table, 0, 2, count, float(position));
        EXPECT_NEAR(found, expected, 1e-4 * count) << "at " << position;
    }
}

TEST(UnevenAxisLookup, HurricaneLevels) {
    // The synthetic hurricane's levels (tools/hurricane): gaps growing linearly to three times the lowest.
    std::vector<double> nodes{0.0};
    const double lowest = 2.0 * 0.4 / (24.0 * 4.0);
    const double growth = (0.4 - lowest * 24.0) / (0.5 * 24.0 * 23.0);
    for (int gap = 0; gap < 24; ++gap) nodes.push_back(nodes.back() + lowest + growth * gap);
    expectLookupMatchesGridAxes(nodes);
    // 96 buckets of half the finest gap: the shaders look up without a loop (UNEVEN_AXIS_WALK 0).
    EXPECT_FALSE(buildUnevenAxisTable(seriesWithZNodes(nodes)).crowdedBuckets);
}

TEST(UnevenAxisLookup, GapsOverFourOrdersOfMagnitude) {
    // Ocean-like depths: 1 m at the top, 5000 m at the bottom; more buckets than the table holds, so
    // the lookup walks several nodes from its bucket.
    std::vector<double> nodes{0.0};
    for (int k = 0; k < 60; ++k) nodes.push_back(nodes.back() + std::pow(10.0, 3.7 * k / 59.0));
    expectLookupMatchesGridAxes(nodes);
    EXPECT_TRUE(buildUnevenAxisTable(seriesWithZNodes(nodes)).crowdedBuckets);
}

TEST(UnevenAxisLookup, TheTableFollowsEachAxisNodes) {
    const Series series = seriesWithZNodes({0.0, 1.0, 3.0, 7.0});
    const UnevenAxisTable table = buildUnevenAxisTable(series);
    // Nodes 0, 1, 3, 7; buckets half the finest gap (1) wide: 14 buckets of 0.5.
    ASSERT_EQ(table.steps.size(), 1u);
    const contract::UnevenAxisInfo& info = table.steps[0];
    EXPECT_EQ(info.firstNode, glm::ivec4(-1, -1, 0, -1));
    EXPECT_EQ(info.firstCell.z, 0);
    EXPECT_EQ(info.bucketCount.z, 14);
    EXPECT_FLOAT_EQ(info.bucketsPerUnit.z, 2.0f);
    EXPECT_EQ(table.positions, (std::vector<float>{0, 1, 3, 7}));
    // Each bucket: the first node after its start, that node's index, and the node indices per unit
    // below and above it (the last node's cell on both sides).
    const glm::vec4 toNode1(1, 1, 1, 0.5f), toNode2(3, 2, 0.5f, 0.25f), toNode3(7, 3, 0.25f, 0.25f);
    const std::vector<glm::vec4> cells{toNode1, toNode1, toNode2, toNode2, toNode2, toNode2, toNode3,
                                       toNode3, toNode3, toNode3, toNode3, toNode3, toNode3, toNode3};
    EXPECT_EQ(table.cells, cells);
    // Position 2 (bucket 4): node index 1 + (2 - 1) / 2 = 1.5, from the record 2 + (2 - 3) * 0.5.
    EXPECT_FLOAT_EQ(lookUpNodeIndex(table, 0, 2, 4, 2.0f), 1.5f);
}

TEST(UnevenAxisLookup, TimeStepsOnTheSameLevelsShareOneList) {
    Series series = seriesWithZNodes({0.0, 1.0, 3.0, 7.0});
    series.steps.push_back(series.steps[0]);
    Series other = seriesWithZNodes({0.0, 2.0, 3.0});
    series.steps.push_back(other.steps[0]);
    const UnevenAxisTable table = buildUnevenAxisTable(series);
    ASSERT_EQ(table.steps.size(), 3u);
    EXPECT_EQ(table.steps[1].firstNode, table.steps[0].firstNode);
    EXPECT_EQ(table.steps[1].firstCell, table.steps[0].firstCell);
    EXPECT_EQ(table.steps[2].firstNode.z, 4);  // after the first list's four nodes
    EXPECT_EQ(table.positions.size(), 4u + 3u);
    EXPECT_FLOAT_EQ(lookUpNodeIndex(table, 2, 2, 3, 2.5f), 1.5f);
}

TEST(UnevenAxisLookup, MoreCellsThanTheGpuHoldsIsAnInputErrorNamingTheManifest) {
    Series series = seriesWithZNodes({0.0, 1.0, 3.0, 7.0});  // 14 cells
    series.manifestPath = "levels/series.json";
    const UnevenAxisTable table = buildUnevenAxisTable(series);
    EXPECT_NO_THROW(requireCellsFit(table, 14, series));
    try {
        requireCellsFit(table, 13, series);
        FAIL() << "no error";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("levels/series.json"), std::string::npos) << message;
        EXPECT_NE(message.find("14 lookup cells"), std::string::npos) << message;
        EXPECT_NE(message.find("(13)"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace tstyles
