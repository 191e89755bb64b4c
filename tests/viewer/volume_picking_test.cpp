// Picking marches the pixel's ray to the first sample some time-step's STF makes visible.
#include <gtest/gtest.h>

#include "viewer/volume_picking.h"

namespace {

using namespace tstyles;
using namespace tstyles::viewer;

// One time-step: a 5x5x5 unit cube whose density is 1 for z <= 0.5 and 0 beyond, seen by an
// orthographic camera from +z. The first visible sample along the central ray is at z = 0.5.
Series halfFullCube() {
    TimeStep step;
    RectilinearGrid grid;
    grid.dims = {5, 5, 5};
    grid.spacing = glm::dvec3(0.25);
    step.grid = grid;
    for (int z = 0; z < 5; ++z)
        for (int i = 0; i < 25; ++i) step.density.push_back(z <= 2 ? 1.0f : 0.0f);
    Series series;
    series.steps.push_back(step);
    return series;
}

Scene lookingDownZ() {
    Scene scene;
    scene.camera.pose = OrbitCamera{glm::dvec3(0.5), 3.0, 0.0, 0.0};
    scene.camera.projection = Projection::Orthographic;
    // Opaque from density 0.5 on (two nodes at one place make a step): between the nodes at
    // z = 0.5 and 0.75 the density falls from 1 to 0, so it reaches 0.5 at z = 0.625.
    scene.stf.curve.opacity = {{0.5, 0.0}, {0.5, 1.0}};
    return scene;
}

TEST(VolumePicking, FindsTheFirstVisibleSample) {
    const Series series = halfFullCube();
    const auto pick = pickFirstVisibleSample(series, lookingDownZ(), {49.5, 49.5}, {100, 100}, 0.001);
    ASSERT_TRUE(pick.has_value());
    EXPECT_NEAR(pick->world.x, 0.5, 0.01);
    EXPECT_NEAR(pick->world.y, 0.5, 0.01);
    EXPECT_NEAR(pick->world.z, 0.625, 0.0011);  // within one step of 0.001
    ASSERT_EQ(pick->densities.size(), 1u);
    EXPECT_NEAR(*pick->densities[0], 0.5, 0.01);
}

TEST(VolumePicking, MissesWhenNothingIsVisible) {
    const Series series = halfFullCube();
    Scene scene = lookingDownZ();
    scene.stf.curve.opacity = {{0.0, 0.0}};
    EXPECT_FALSE(pickFirstVisibleSample(series, scene, {50, 50}, {100, 100}, 0.01).has_value());
    // A pixel whose ray passes beside the data.
    EXPECT_FALSE(pickFirstVisibleSample(series, lookingDownZ(), {0, 0}, {100, 100}, 0.01).has_value());
}

}  // namespace
