// Beam (sonar) grid geometry: sample positions and their inverse, uneven beam angles, and the
// fan's enclosing mesh, against closed-form values.
#include <gtest/gtest.h>

#include <cmath>

#include "tstyles/data/beam_geometry.h"

namespace {

tstyles::BeamGrid fan() {
    tstyles::BeamGrid grid;
    grid.dims = {9, 7, 41};
    grid.azimuthDeg = tstyles::evenBeamAngles(-30.0, 30.0, 9);
    grid.elevationDeg = {-20.0, -12.0, -5.0, 0.0, 4.0, 11.0, 20.0};  // uneven
    grid.minRange = 2.0;
    grid.maxRange = 10.0;
    return grid;
}

TEST(BeamGeometry, SamplePositionsMapBackToTheirIndices) {
    const tstyles::BeamGrid grid = fan();
    for (int k : {0, 17, 40})
        for (int j = 0; j < 7; ++j)
            for (int i = 0; i < 9; i += 4) {
                const glm::dvec3 local = tstyles::beamSamplePosition(grid, i, j, k);
                EXPECT_NEAR(glm::length(local), 2.0 + 0.2 * k, 1e-12);
                const auto voxel = tstyles::beamVoxel(grid, local);
                ASSERT_TRUE(voxel.has_value());
                EXPECT_NEAR(voxel->x, i, 1e-9);
                EXPECT_NEAR(voxel->y, j, 1e-9);
                EXPECT_NEAR(voxel->z, k, 1e-9);
            }
}

TEST(BeamGeometry, PositionsOutsideTheFanHaveNoVoxel) {
    const tstyles::BeamGrid grid = fan();
    EXPECT_FALSE(tstyles::beamVoxel(grid, {0.0, 0.0, 1.9}).has_value());   // before the near range
    EXPECT_FALSE(tstyles::beamVoxel(grid, {0.0, 0.0, 10.1}).has_value());  // beyond the far range
    EXPECT_FALSE(tstyles::beamVoxel(grid, {0.0, 0.0, -5.0}).has_value());  // behind the transducer
    // 31 degrees of azimuth is beyond the last beam at 30.
    EXPECT_FALSE(tstyles::beamVoxel(grid, {5.0 * std::tan(glm::radians(31.0)), 0.0, 5.0}).has_value());
    EXPECT_TRUE(tstyles::beamVoxel(grid, {5.0 * std::tan(glm::radians(29.0)), 0.0, 5.0}).has_value());
}

TEST(BeamGeometry, UnevenAnglesInterpolateLinearlyBetweenBeams) {
    const std::vector<double> angles{-20.0, -12.0, -5.0, 0.0, 4.0, 11.0, 20.0};
    EXPECT_NEAR(*tstyles::fractionalBeamIndex(angles, 2.0), 3.5, 1e-12);
    EXPECT_NEAR(*tstyles::fractionalBeamIndex(angles, -16.0), 0.5, 1e-12);
    EXPECT_NEAR(*tstyles::fractionalBeamIndex(angles, 20.0), 6.0, 1e-12);
    EXPECT_FALSE(tstyles::fractionalBeamIndex(angles, 20.5).has_value());
    EXPECT_FALSE(tstyles::areEvenBeamAngles(angles));
    EXPECT_TRUE(tstyles::areEvenBeamAngles(tstyles::evenBeamAngles(-30.0, 30.0, 25)));
}

TEST(BeamGeometry, FanBoundaryEnclosesTheFarCapAndFacesOutward) {
    const tstyles::BeamGrid grid = fan();
    const auto mesh = tstyles::beamFanBoundary(grid);
    ASSERT_FALSE(mesh.empty());
    const glm::dvec3 inside = tstyles::beamSamplePosition(grid, 4, 3, 20);
    for (const auto& triangle : mesh) {
        const glm::dvec3 normal = glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]);
        // The fan is convex apart from its near cap; every face plane keeps the inner point behind it.
        const glm::dvec3 centre = (triangle[0] + triangle[1] + triangle[2]) / 3.0;
        if (glm::length(centre) > 2.5) {
            EXPECT_LT(glm::dot(normal, inside - centre), 0.0);
        }
        // No facet comes closer to the far cap's sphere from outside: every far-cap corner at >= maxRange.
        for (const auto& corner : triangle)
            if (glm::length(corner) > 5.0) {
                EXPECT_GE(glm::length(corner), grid.maxRange);
            }
    }
}

TEST(BeamGeometry, FinestSpacingIsTheRangeSpacingForLongFans) {
    EXPECT_NEAR(tstyles::beamFinestSpacing(fan()), 0.2, 1e-12);
}

}  // namespace
