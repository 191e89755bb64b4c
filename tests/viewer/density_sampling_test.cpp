// CPU density lookups (picking) against known answers: grid nodes give their values, points
// between them the trilinear mix, placement (origin and rotation) is undone, outside is none.
#include <gtest/gtest.h>

#include <numbers>

#include "tstyles/data/density_sampling.h"

namespace {

using namespace tstyles;

// A 3x3x3 grid with density = (x + 2y + 4z) / 18 at node (x, y, z): linear, so trilinear
// interpolation reproduces it exactly everywhere inside.
TimeStep linearStep(const Placement& placement) {
    TimeStep step;
    RectilinearGrid grid;
    grid.dims = {3, 3, 3};
    grid.spacing = {0.5, 0.5, 0.5};
    step.grid = grid;
    step.placement = placement;
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) step.density.push_back(float(x + 2 * y + 4 * z) / 18.0f);
    return step;
}

double expected(const glm::dvec3& voxel) { return (voxel.x + 2.0 * voxel.y + 4.0 * voxel.z) / 18.0; }

TEST(DensitySampling, NodesAndPointsBetweenThem) {
    const TimeStep step = linearStep({});
    EXPECT_NEAR(*sampleDensity(step, {0.0, 0.0, 0.0}), 0.0, 1e-7);
    EXPECT_NEAR(*sampleDensity(step, {1.0, 1.0, 1.0}), expected({2, 2, 2}), 1e-7);
    EXPECT_NEAR(*sampleDensity(step, {0.3, 0.7, 0.45}), expected({0.6, 1.4, 0.9}), 1e-6);
}

TEST(DensitySampling, OutsideTheGridThereIsNoDensity) {
    const TimeStep step = linearStep({});
    EXPECT_FALSE(sampleDensity(step, {-0.01, 0.5, 0.5}).has_value());
    EXPECT_FALSE(sampleDensity(step, {0.5, 1.01, 0.5}).has_value());
    EXPECT_TRUE(sampleDensity(step, {1.0, 1.0, 1.0}).has_value());
}

TEST(DensitySampling, PlacementIsUndone) {
    Placement placement;
    placement.origin = {10.0, 0.0, 0.0};
    // A quarter turn about z: grid x points along world y.
    placement.rotation = fromAxisAngle({{0.0, 0.0, 1.0}, 90.0});
    const TimeStep step = linearStep(placement);
    // Grid-local (0.5, 0, 0) (voxel (1, 0, 0)) is at world (10, 0.5, 0).
    EXPECT_NEAR(*sampleDensity(step, {10.0, 0.5, 0.0}), expected({1, 0, 0}), 1e-6);
    EXPECT_FALSE(sampleDensity(step, {10.5, 0.0, 0.0}).has_value());
}

TEST(DensitySampling, TemporalProfileHasOneValuePerTimeStep) {
    Series series;
    series.steps.push_back(linearStep({}));
    Placement shifted;
    shifted.origin = {0.5, 0.0, 0.0};
    series.steps.push_back(linearStep(shifted));
    const auto profile = temporalProfile(series, {0.25, 0.0, 0.0});
    ASSERT_EQ(profile.size(), 2u);
    EXPECT_NEAR(*profile[0], expected({0.5, 0, 0}), 1e-6);
    EXPECT_FALSE(profile[1].has_value());
}

// Missing voxels: the mix of the corners with data divided by their weight, and "no data" where
// those corners weigh less than half (as the renderer decides).
TEST(DensitySampling, MissingCornersAreLeftOutAndMostlyMissingIsNoData) {
    TimeStep step = linearStep({});
    step.density[0] = missingDensity();  // node (0, 0, 0)
    // Halfway between node (0,0,0) (missing) and (1,0,0): only (1,0,0) has data.
    EXPECT_NEAR(*sampleDensity(step, {0.25, 0.0, 0.0}), expected({1, 0, 0}), 1e-6);
    // At the missing node itself the valid corners weigh nothing: no data.
    EXPECT_TRUE(isMissing(*sampleDensity(step, {0.0, 0.0, 0.0})));
    // A quarter of the way from (1,0,0) to (0,0,0): the missing corner weighs 0.25, (1,0,0) 0.75.
    EXPECT_NEAR(*sampleDensity(step, {0.375, 0.0, 0.0}), expected({1, 0, 0}), 1e-6);
    // Three quarters towards the missing node: 0.25 of valid weight is below half, so no data.
    EXPECT_TRUE(isMissing(*sampleDensity(step, {0.125, 0.0, 0.0})));
}

TEST(DensitySampling, UnevenAxesMapPositionsThroughTheirNodes) {
    TimeStep step = linearStep({});
    RectilinearGrid grid = step.rectilinear();
    grid.axisPositions[2] = {0.0, 0.2, 1.0};  // z nodes at 0, 0.2, 1.0 instead of 0, 0.5, 1.0
    step.grid = grid;
    EXPECT_NEAR(*sampleDensity(step, {0.0, 0.0, 0.2}), expected({0, 0, 1}), 1e-6);
    EXPECT_NEAR(*sampleDensity(step, {0.0, 0.0, 0.6}), expected({0, 0, 1.5}), 1e-6);
    EXPECT_NEAR(*sampleDensity(step, {0.0, 0.0, 0.1}), expected({0, 0, 0.5}), 1e-6);
    EXPECT_FALSE(sampleDensity(step, {0.0, 0.0, 1.01}).has_value());
}

}  // namespace
