// The bucket lookup of uneven axes (render/uneven_axis_table.h, mirrored by the shaders' nodeIndexOf)
// gives the same fractional node index as the data model's inverse of the axis (data/grid_axes.h),
// on the synthetic hurricane's levels (one step from the bucket's node, no loop) and on an axis
// whose gaps span four orders of magnitude (a walk, UNEVEN_AXIS_WALK).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

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
    ASSERT_EQ(table.firstNode.size(), 1u);
    const int first = table.firstNode[0].z;
    const int count = int(nodes.size());
    ASSERT_GE(first, 0);
    std::vector<double> positions = nodes;
    for (int i = -100; i <= 10100; ++i) positions.push_back(nodes.back() * i / 10000.0);
    for (const double position : positions) {
        const double expected = std::clamp(fractionalIndex(grid, 2, position), 0.0, double(count - 1));
        const float found = lookUpNodeIndex(table, first, count, float(position));
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
    ASSERT_EQ(table.firstNode[0], glm::ivec4(-1, -1, 0, -1));
    ASSERT_EQ(table.positions.size(), 4u + 2u + 14u);
    EXPECT_FLOAT_EQ(table.positions[4], 2.0f);
    EXPECT_FLOAT_EQ(table.positions[5], 14.0f);
    const std::vector<float> lowerNodes{0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2};
    EXPECT_EQ(std::vector<float>(table.positions.begin() + 6, table.positions.end()), lowerNodes);
}

}  // namespace
}  // namespace tstyles
