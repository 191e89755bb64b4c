// The coast of a map (src/annotate/coastline.h): the edges between the surface's missing values and
// its data, at the surface, on known grids.
#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include "../../src/annotate/coastline.h"

namespace tstyles {
namespace {

// One time-step on a 4 x 2 x 3 grid of unit spacing, land (missing values) where x < 2 at grid level
// `landLevel` of y.
Series landOnTheWest(int landLevel, const glm::dquat& rotation = glm::dquat(1.0, 0.0, 0.0, 0.0)) {
    TimeStep step;
    RectilinearGrid grid;
    grid.dims = {4, 2, 3};
    grid.spacing = glm::dvec3(1.0);
    step.grid = grid;
    step.placement.rotation = rotation;
    step.density.assign(grid.voxelCount(), 0.5f);
    for (int z = 0; z < 3; ++z)
        for (int x = 0; x < 2; ++x) step.density[std::size_t((z * 2 + landLevel) * 4 + x)] = missingDensity();
    Series series;
    series.steps.push_back(std::move(step));
    return series;
}

TEST(Coastline, AnEdgeBetweenLandAndSeaAtTheSurface) {
    // y runs up the display: the surface is y = 1; the coast runs along z at x = 1.5, cut to the grid.
    const std::vector<WorldSegment> segments = coastSegments(landOnTheWest(1));
    ASSERT_EQ(segments.size(), 3u);
    const double ends[4] = {0.0, 0.5, 1.5, 2.0};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(segments[i].first, glm::dvec3(1.5, 1.0, ends[i])) << i;
        EXPECT_EQ(segments[i].second, glm::dvec3(1.5, 1.0, ends[i + 1])) << i;
    }
    // Land below the surface only (a shelf): no coast.
    EXPECT_TRUE(coastSegments(landOnTheWest(0)).empty());
}

TEST(Coastline, TheSurfaceIsTheTopInTheDisplay) {
    // Turned upside down about x, grid level 0 is the top: the coast is there, at world y = 0.
    const glm::dquat flipped = glm::angleAxis(glm::radians(180.0), glm::dvec3(1.0, 0.0, 0.0));
    const std::vector<WorldSegment> segments = coastSegments(landOnTheWest(0, flipped));
    ASSERT_EQ(segments.size(), 3u);
    for (const auto& [from, to] : segments) {
        EXPECT_NEAR(from.x, 1.5, 1e-12);
        EXPECT_NEAR(from.y, 0.0, 1e-12);
        EXPECT_NEAR(to.y, 0.0, 1e-12);
    }
    EXPECT_TRUE(coastSegments(landOnTheWest(1, flipped)).empty());
}

}  // namespace
}  // namespace tstyles
