// Explicit structured grids: point location on a warped box whose mapping is known in closed form,
// the inverse map's error against exact point location, and grids that must be refused.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "tstyles/data/density_sampling.h"
#include "tstyles/data/inverse_map.h"
#include "tstyles/data/series.h"
#include "tstyles/data/structured_point_location.h"
#include "tstyles/data/warped_box.h"

namespace tstyles {
namespace {

double maxComponent(glm::dvec3 v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

TEST(StructuredGrid, BoundsAndFinestEdgeComeFromTheNodes) {
    const WarpedBox box;
    const StructuredGrid grid = box.grid();
    EXPECT_EQ(grid.dims, box.dims);
    // x = i h + 0.15 sin(pi t) >= 0: the lower x bound is 0 (at the corners), the upper one
    // 1 + 0.15 (the +x face's middle row, t = 0.5).
    EXPECT_NEAR(grid.localLower.x, 0.0, 1e-6);
    EXPECT_NEAR(grid.localUpper.x, 1.15, 1e-6);
    EXPECT_NEAR(grid.localUpper.y, 1.1, 1e-6);
    EXPECT_NEAR(grid.localUpper.z, 0.5, 1e-6);
    // Edges along z are exactly h long; the bent edges are a little longer.
    EXPECT_NEAR(grid.finestEdge, box.spacing, 1e-6);
}

TEST(StructuredGrid, NodeCountMustMatchDims) {
    EXPECT_THROW(makeStructuredGrid({2, 2, 2}, std::vector<glm::vec3>(7)), std::invalid_argument);
}

TEST(StructuredPointLocation, FindsTheComputationalCoordinatesOfPointsInsideTheGrid) {
    const WarpedBox box;
    const StructuredGrid grid = box.grid();
    const StructuredPointLocator locator(grid);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int sample = 0; sample < 2000; ++sample) {
        const glm::dvec3 computational = glm::dvec3(unit(random), unit(random), unit(random)) * glm::dvec3(grid.dims - 1);
        // The grid's own (trilinear) mapping, so the answer is exact.
        const glm::dvec3 point = positionAtComputational(grid, computational);
        const auto found = locator.locate(point);
        ASSERT_TRUE(found) << "sample " << sample;
        EXPECT_LT(maxComponent(*found - computational), 1e-6) << "sample " << sample;
    }
}

TEST(StructuredPointLocation, NodesSitOnTheClosedFormMapping) {
    const WarpedBox box;
    const StructuredGrid grid = box.grid();
    const StructuredPointLocator locator(grid);
    for (const glm::ivec3 node : {glm::ivec3(0, 0, 0), glm::ivec3(8, 8, 4), glm::ivec3(16, 3, 8), glm::ivec3(5, 16, 2)}) {
        const auto found = locator.locate(box.position(glm::dvec3(node)));
        ASSERT_TRUE(found) << "node " << node.x << ", " << node.y << ", " << node.z;
        EXPECT_LT(maxComponent(*found - glm::dvec3(node)), 1e-5);
    }
    // Between nodes the grid is trilinear, the closed form a sine: they differ by at most
    // A (pi h / L)^2 / 8 in position, 0.15 * (pi / 16)^2 / 8 = 7.2e-4, i.e. 0.012 cells.
    const auto middle = locator.locate(box.position({8.5, 8.5, 4.5}));
    ASSERT_TRUE(middle);
    EXPECT_LT(maxComponent(*middle - glm::dvec3(8.5, 8.5, 4.5)), 0.012);
}

TEST(StructuredPointLocation, PointsOutsideTheCurvedBoundaryAreNotFound) {
    const WarpedBox box;
    const StructuredGrid grid = box.grid();
    const StructuredPointLocator locator(grid);
    // At the middle row the -x face bulges to x = 0.15; a point at x = 0.1 is inside the bounding
    // box but outside the grid.
    EXPECT_FALSE(locator.locate(glm::dvec3(0.1, 0.5, 0.25)));
    EXPECT_TRUE(locator.locate(glm::dvec3(0.2, 0.5, 0.25)));
    EXPECT_FALSE(locator.locate(glm::dvec3(0.5, 0.5, 0.6)));  // above the top face
}

// The inverse map against exact point location at random points: this is the error the renderer
// makes when it finds a sample's computational coordinates (docs/structured-grids.md).
struct MapError {
    double max = 0.0;
    double mean = 0.0;
    int misclassified = 0;
};

MapError measureInverseMapError(const StructuredGrid& grid, const InverseMap& map, int samples) {
    const StructuredPointLocator locator(grid);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    MapError error;
    int inside = 0;
    while (inside < samples) {
        const glm::dvec3 point = grid.localLower + glm::dvec3(unit(random), unit(random), unit(random)) *
                                                       (grid.localUpper - grid.localLower);
        const auto exact = locator.locate(point);
        const glm::vec4 mapped = map.lookup(point);
        if (!exact) {
            // Outside the grid the map may only claim "inside" within one texel of the boundary.
            continue;
        }
        ++inside;
        if (!(mapped.a > 0.0f)) ++error.misclassified;
        const double difference = maxComponent(glm::dvec3(mapped) - *exact);
        error.max = std::max(error.max, difference);
        error.mean += difference / samples;
    }
    return error;
}

TEST(InverseMap, ErrorAgainstExactPointLocationIsWithinTheStatedBound) {
    const WarpedBox box;
    const StructuredGrid grid = box.grid();
    for (int texelsPerCell : {1, 2, 4}) {
        const InverseMap map = buildInverseMap(grid, inverseMapDims(grid, texelsPerCell));
        const MapError error = measureInverseMapError(grid, map, 20000);
        std::printf("inverse map %d texel(s) per cell (%dx%dx%d, %zu bytes): max error %.4f cells, mean %.5f cells\n",
                    texelsPerCell, map.dims.x, map.dims.y, map.dims.z, map.bytes(), error.max, error.mean);
        EXPECT_EQ(error.misclassified, 0);
        // The stated bounds (docs/structured-grids.md): at the default of 2 texels per cell max 0.02
        // cell and mean 0.004 cell (measured 0.013 and 0.0023); at 1 texel per cell max 0.1 cell.
        if (texelsPerCell == 2) {
            EXPECT_LT(error.max, 0.02);
            EXPECT_LT(error.mean, 0.004);
        }
        if (texelsPerCell == 1) {
            EXPECT_LT(error.max, 0.1);
        }
    }
}

TEST(InverseMap, MemoryIsSixteenBytesPerTexel) {
    const StructuredGrid grid = WarpedBox{}.grid();
    const InverseMap map = buildInverseMap(grid, inverseMapDims(grid));
    EXPECT_EQ(map.dims, glm::ivec3(33, 33, 17));
    EXPECT_EQ(map.bytes(), std::size_t(33 * 33 * 17 * 16));
}

TEST(StructuredGridProblems, InvertedDegenerateAndNonFiniteCellsAreNamed) {
    const StructuredGrid good = WarpedBox{}.grid();
    EXPECT_FALSE(findGridProblem(good));

    std::vector<glm::vec3> nodes = *good.nodes;
    std::swap(nodes[good.nodeIndex(3, 4, 5)], nodes[good.nodeIndex(4, 4, 5)]);
    const auto inverted = findGridProblem(makeStructuredGrid(good.dims, nodes));
    ASSERT_TRUE(inverted);
    EXPECT_NE(inverted->find("inverted"), std::string::npos) << *inverted;
    EXPECT_NE(inverted->find("corner node (3, 4, 5)"), std::string::npos) << *inverted;

    nodes = *good.nodes;
    nodes[good.nodeIndex(1, 0, 0)] = nodes[good.nodeIndex(0, 0, 0)];
    const auto degenerate = findGridProblem(makeStructuredGrid(good.dims, nodes));
    ASSERT_TRUE(degenerate);
    EXPECT_NE(degenerate->find("cell (0, 0, 0) is degenerate"), std::string::npos) << *degenerate;

    nodes = *good.nodes;
    nodes[good.nodeIndex(2, 2, 2)].y = std::nanf("");
    const auto notFinite = findGridProblem(makeStructuredGrid(good.dims, nodes));
    ASSERT_TRUE(notFinite);
    EXPECT_NE(notFinite->find("node (2, 2, 2) has a non-finite coordinate"), std::string::npos) << *notFinite;
}

TEST(StructuredGridProblems, LeftHandedGridsAreFineWhenEveryCellAgrees) {
    // Mirrored in x, every cell is left-handed: consistent, so not inverted; point location works.
    std::vector<glm::vec3> nodes = *WarpedBox{}.grid().nodes;
    for (glm::vec3& node : nodes) node.x = -node.x;
    const StructuredGrid mirrored = makeStructuredGrid(WarpedBox{}.dims, nodes);
    EXPECT_FALSE(findGridProblem(mirrored));
    const auto found = StructuredPointLocator(mirrored).locate(positionAtComputational(mirrored, {4.5, 6.25, 3.0}));
    ASSERT_TRUE(found);
    EXPECT_LT(maxComponent(*found - glm::dvec3(4.5, 6.25, 3.0)), 1e-6);
}

TEST(StructuredSeries, WorldBoundsAndFinestSpacingFollowTheNodes) {
    Series series;
    TimeStep step;
    step.grid = WarpedBox{}.grid();
    step.placement.origin = {1.0, 2.0, 3.0};
    series.steps.push_back(step);
    const Bounds bounds = series.worldBounds();
    EXPECT_NEAR(bounds.lower.x, 1.0, 1e-6);
    EXPECT_NEAR(bounds.upper.x, 2.15, 1e-6);
    EXPECT_NEAR(bounds.upper.z, 3.5, 1e-6);
    EXPECT_NEAR(series.finestSpacing(), 1.0 / 16.0, 1e-6);
    EXPECT_EQ(series.steps[0].dims(), glm::ivec3(17, 17, 9));
    EXPECT_EQ(gridTypeName(series.steps[0].grid), "structured");
}

TEST(StructuredSeries, CpuDensitySamplingLocatesThePointInTheGrid) {
    // Density i / (nx - 1) on the warped box, placed at an offset: sampling at the world position of
    // computational coordinates (i, j, k) gives back i / (nx - 1), as picking in the viewer needs.
    const WarpedBox box;
    Series series;
    for (int copy = 0; copy < 2; ++copy) {
        TimeStep step;
        step.grid = box.grid();
        step.placement.origin = {1.0, 0.0, 0.0};
        for (int k = 0; k < box.dims.z; ++k)
            for (int j = 0; j < box.dims.y; ++j)
                for (int i = 0; i < box.dims.x; ++i) step.density.push_back(float(i) / float(box.dims.x - 1));
        series.steps.push_back(step);
    }
    const StructuredGrid& grid = *series.steps[0].structured();
    for (const glm::dvec3 computational : {glm::dvec3(3.25, 7.5, 2.0), glm::dvec3(12.8, 1.1, 6.6)}) {
        const glm::dvec3 world = glm::dvec3(1.0, 0.0, 0.0) + positionAtComputational(grid, computational);
        const auto density = sampleDensity(series.steps[0], world);
        ASSERT_TRUE(density);
        EXPECT_NEAR(*density, computational.x / (box.dims.x - 1), 1e-5);
        const auto profile = temporalProfile(series, world);
        ASSERT_EQ(profile.size(), 2u);
        ASSERT_TRUE(profile[1]);
        EXPECT_NEAR(*profile[1], *density, 1e-9);
    }
    // Inside the bounding box, outside the bent -x face: no density.
    EXPECT_FALSE(sampleDensity(series.steps[0], {1.1, 0.5, 0.25}));
}

}  // namespace
}  // namespace tstyles
