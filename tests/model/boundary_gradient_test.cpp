// The value gradient that unchanged places keep their boundaries by (boundary_gradient.h), on a
// ramp whose slope is known.
#include <vector>

#include <gtest/gtest.h>

#include "tstyles/scene/boundary_gradient.h"

namespace tstyles {
namespace {

// 6 x 3 x 2 nodes, 0.5 apart along x (uneven along y: 0, 1, 3), density 0.1 + 0.05 x: a slope of 0.1
// per unit length along x, none along y and z.
TimeStep ramp() {
    TimeStep step;
    RectilinearGrid grid;
    grid.dims = {6, 3, 2};
    grid.spacing = {0.5, 1.0, 2.0};
    grid.axisPositions[1] = {0.0, 1.0, 3.0};
    step.grid = grid;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 6; ++x) step.density.push_back(float(0.1 + 0.05 * x));
    return step;
}

Stf visibleAbove(double density) {
    Stf stf;
    stf.curve.opacity = {{0.0, 0.0}, {density, 0.0}, {density + 1e-6, 1.0}};
    return stf;
}

TEST(BoundaryGradient, ARampsSlopeEverywhereItIsSeen) {
    std::vector<double> magnitudes;
    addGradientMagnitudes(ramp(), visibleAbove(0.0), 1, magnitudes);
    ASSERT_EQ(magnitudes.size(), 36u);
    for (double magnitude : magnitudes) EXPECT_NEAR(magnitude, 0.1, 1e-6);  // one-sided at the faces too
    EXPECT_NEAR(boundaryGradientOf(magnitudes), 0.1, 1e-6);
    // Only the nodes the STF shows: x = 3, 4, 5 (densities 0.25 .. 0.35), 6 of each.
    magnitudes.clear();
    addGradientMagnitudes(ramp(), visibleAbove(0.22), 1, magnitudes);
    EXPECT_EQ(magnitudes.size(), 18u);
    EXPECT_EQ(boundaryGradientOf({}), 0.0);
}

TEST(BoundaryGradient, OneSidedBesideMissingValues) {
    TimeStep step = ramp();
    step.density[2] = missingDensity();  // node (2, 0, 0): its neighbours take their other side
    std::vector<double> magnitudes;
    addGradientMagnitudes(step, visibleAbove(0.0), 1, magnitudes);
    ASSERT_EQ(magnitudes.size(), 35u);
    for (double magnitude : magnitudes) EXPECT_NEAR(magnitude, 0.1, 1e-6);
}

TEST(BoundaryGradient, TheNinetyNinthPercentile) {
    std::vector<double> magnitudes(1000, 0.01);
    for (int i = 0; i < 20; ++i) magnitudes[std::size_t(i)] = 1.0;  // 2 % steep boundaries
    EXPECT_EQ(boundaryGradientOf(magnitudes), 1.0);
    for (int i = 0; i < 10; ++i) magnitudes[std::size_t(i)] = 0.01;  // 1 %: below the percentile
    EXPECT_EQ(boundaryGradientOf(magnitudes), 0.01);
}

}  // namespace
}  // namespace tstyles
