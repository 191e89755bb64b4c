// The probe lands where the ray mode's picture takes the pixel from (ProbeDepth), on closed-form
// cases: a cube seen straight down its z axis by an orthographic camera.
#include <gtest/gtest.h>

#include "tstyles/scene/ray_modes.h"
#include "viewer/volume_picking.h"

namespace {

using namespace tstyles;
using namespace tstyles::viewer;

constexpr glm::dvec2 kCentre{49.5, 49.5};
constexpr glm::ivec2 kViewport{100, 100};

// A unit cube of 5x5x5 nodes (spacing 0.25) whose density at node layer k (z = k / 4) is
// densities[k], the same in every time-step unless `later` gives the second one's.
Series layeredCube(const std::vector<float>& densities, const std::vector<float>& later = {}) {
    Series series;
    for (const auto* layers : {&densities, &later}) {
        if (layers->empty()) continue;
        TimeStep step;
        RectilinearGrid grid;
        grid.dims = {5, 5, 5};
        grid.spacing = glm::dvec3(0.25);
        step.grid = grid;
        for (int z = 0; z < 5; ++z)
            for (int i = 0; i < 25; ++i) step.density.push_back((*layers)[std::size_t(z)]);
        step.time = double(series.steps.size());
        series.steps.push_back(step);
    }
    return series;
}

// Seen from +z: rays enter at z = 1 and travel toward z = 0.
Scene lookingDownZ() {
    Scene scene;
    scene.camera.pose = OrbitCamera{glm::dvec3(0.5), 3.0, 0.0, 0.0};
    scene.camera.projection = Projection::Orthographic;
    return scene;
}

// The probe under the view's centre pixel, marching in steps of 0.01 with the reference length of
// the cube's spacing.
std::optional<glm::dvec3> probeAtCentre(const Series& series, const Scene& scene) {
    return probePlaceUnder(series, scene, kCentre, kViewport, 0.01, 0.25);
}

TEST(ProbePlacing, CompositedRaysLandWhereHalfTheOpacityIsGathered) {
    // Density 1 in the layers z <= 0.5, 0 above, falling linearly between z = 0.75 and 0.5: the STF
    // shows 0.6 opacity above density 0.45, so below z = 0.6375. With a step of 1/8 of the
    // reference length each sample there adds 1 - 0.4^(1/8): 0.4^(n/8) first falls to 0.5 or
    // below at n = 7 (n >= 8 log 0.5 / log 0.4 = 6.05). Samples stand at z = 1 - k/32 from the
    // top; the first below 0.6375 is k = 12, so the 7th is k = 18: z = 0.4375.
    const Series series = layeredCube({1, 1, 1, 0, 0});
    Scene scene = lookingDownZ();
    scene.stf.curve.opacity = {{0.45, 0.0}, {0.45, 0.6}};
    const double step = 0.25 / 8.0;
    ASSERT_EQ(rayModeInfo(scene.rayMode).probeDepth, ProbeDepth::HalfOpacity);
    const auto place = probePlaceUnder(series, scene, kCentre, kViewport, step, 0.25);
    ASSERT_TRUE(place.has_value());
    EXPECT_NEAR(place->x, 0.5, 1e-9);
    EXPECT_NEAR(place->y, 0.5, 1e-9);
    EXPECT_NEAR(place->z, 0.4375, 1e-9);
}

TEST(ProbePlacing, MaximumRaysLandOnTheLargestValue) {
    // Densities along z: 0.2, 0.9 (at z = 0.25), 0.4, 0.6, 0.1. The pixel shows the 0.9.
    Scene scene = lookingDownZ();
    scene.rayMode = rayModeNamed("maximum");
    scene.stf.curve.opacity = {{0.0, 0.0}, {1.0, 1.0}};
    ASSERT_EQ(rayModeInfo(scene.rayMode).probeDepth, ProbeDepth::LargestValue);
    const auto place = probeAtCentre(layeredCube({0.2f, 0.9f, 0.4f, 0.6f, 0.1f}), scene);
    ASSERT_TRUE(place.has_value());
    EXPECT_NEAR(place->z, 0.25, 0.01);
}

TEST(ProbePlacing, MinimumRaysLandOnTheSmallestValueTheStfShows) {
    // Densities along z: 0.3, 0.9, 0.2 (at z = 0.5), 0.6, 0.8: the smallest is the 0.2.
    const Series series = layeredCube({0.3f, 0.9f, 0.2f, 0.6f, 0.8f});
    Scene scene = lookingDownZ();
    scene.rayMode = rayModeNamed("minimum");
    scene.stf.curve.opacity = {{0.0, 1.0}};
    ASSERT_EQ(rayModeInfo(scene.rayMode).probeDepth, ProbeDepth::SmallestValue);
    auto place = probeAtCentre(series, scene);
    ASSERT_TRUE(place.has_value());
    EXPECT_NEAR(place->z, 0.5, 0.01);
    // Densities 0.2 up to z = 0.5, then 0.6 and 0.8, and an STF that shows them from 0.25 up: the
    // 0.2 does not count, and the smallest shown lies just above 0.25 on the slope above z = 0.5,
    // at z = 0.5 + 0.25 * 0.05 / 0.4 = 0.53125 (within a step).
    const Series floor = layeredCube({0.2f, 0.2f, 0.2f, 0.6f, 0.8f});
    scene.stf.curve.opacity = {{0.25, 0.0}, {0.25, 1.0}};
    place = probeAtCentre(floor, scene);
    ASSERT_TRUE(place.has_value());
    EXPECT_NEAR(place->z, 0.53125, 0.01);
}

TEST(ProbePlacing, LargestChangeRaysLandWhereTheTimeStepsDifferMost) {
    // Two time-steps equal but for layer z = 0.75, where one holds 0.1 and the other 0.8.
    const Series series = layeredCube({0.5f, 0.5f, 0.5f, 0.1f, 0.5f}, {0.5f, 0.5f, 0.5f, 0.8f, 0.5f});
    Scene scene = lookingDownZ();
    scene.rayMode = rayModeNamed("largest-change");
    ASSERT_EQ(rayModeInfo(scene.rayMode).probeDepth, ProbeDepth::LargestChange);
    const auto place = probeAtCentre(series, scene);
    ASSERT_TRUE(place.has_value());
    EXPECT_NEAR(place->z, 0.75, 0.01);
}

TEST(ProbePlacing, IsosurfaceRaysLandOnTheFirstCrossing) {
    // Densities along z: 0, 0, 0.2 (z = 0.5), 0.6 (z = 0.75), 1 (z = 1); the iso-value 0.7 is
    // crossed first from above, a quarter of the way from z = 0.75 to 1: at z = 0.8125 exactly
    // (linear between samples, and the trilinear density is linear along z between nodes).
    const Series series = layeredCube({0.0f, 0.0f, 0.2f, 0.6f, 1.0f});
    Scene scene = lookingDownZ();
    scene.rayMode = rayModeNamed("isosurface");
    scene.rayOptions.values["values"] = std::vector<double>{0.7};
    ASSERT_EQ(rayModeInfo(scene.rayMode).probeDepth, ProbeDepth::FirstCrossing);
    const auto place = probeAtCentre(series, scene);
    ASSERT_TRUE(place.has_value());
    // Within the float32 densities' rounding (0.6f is 0.6 + 2.4e-8): 1.1e-8 measured.
    EXPECT_NEAR(place->z, 0.8125, 3e-8);
}

TEST(ProbePlacing, MissesWhereNothingShows) {
    const Series series = layeredCube({1, 1, 1, 0, 0});
    Scene scene = lookingDownZ();
    scene.stf.curve.opacity = {{0.0, 0.0}};
    EXPECT_FALSE(probeAtCentre(series, scene).has_value());
    // A pixel whose ray passes beside the data.
    scene.stf.curve.opacity = {{0.0, 1.0}};
    EXPECT_FALSE(probePlaceUnder(series, scene, {0, 0}, kViewport, 0.01, 0.25).has_value());
}

}  // namespace
