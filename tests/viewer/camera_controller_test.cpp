// Camera moves against closed-form expectations: orbit in degrees per pixel, pan keeps the
// target's screen motion equal to the mouse's, zoom scales the distance, fit forgets distance.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "viewer/camera_controller.h"

namespace {

using namespace tstyles;
using namespace tstyles::viewer;

const Bounds kUnitCube{glm::dvec3(0.0), glm::dvec3(1.0)};
constexpr glm::ivec2 kViewport{400, 300};

glm::dvec2 screenPosition(const Camera& camera, const glm::dvec3& world) {
    const View view = resolveView(camera, kUnitCube, kViewport.x, kViewport.y);
    const glm::dvec4 clip = view.projectionMatrix * view.viewMatrix * glm::dvec4(world, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {(ndc.x + 1.0) * 0.5 * kViewport.x, (1.0 - ndc.y) * 0.5 * kViewport.y};
}

TEST(CameraController, OrbitTurnsByDegreesPerPixel) {
    Camera camera;
    camera.pose = OrbitCamera{std::nullopt, std::nullopt, 10.0, 20.0};
    orbitCamera(camera, {100.0, -50.0});
    const auto& orbit = std::get<OrbitCamera>(camera.pose);
    EXPECT_NEAR(orbit.azimuthDeg, 10.0 - 100.0 * kOrbitDegreesPerPixel, 1e-12);
    EXPECT_NEAR(orbit.elevationDeg, 20.0 - 50.0 * kOrbitDegreesPerPixel, 1e-12);
    // Target and distance stay as they were: unset, framing the data.
    EXPECT_FALSE(orbit.target.has_value());
    EXPECT_FALSE(orbit.distance.has_value());
}

TEST(CameraController, OrbitStopsShortOfThePolesAndWrapsAzimuth) {
    Camera camera;
    camera.pose = OrbitCamera{std::nullopt, std::nullopt, 170.0, 80.0};
    orbitCamera(camera, {-100.0, 1000.0});
    const auto& orbit = std::get<OrbitCamera>(camera.pose);
    EXPECT_NEAR(orbit.azimuthDeg, -160.0, 1e-9);
    EXPECT_EQ(orbit.elevationDeg, 89.0);
}

TEST(CameraController, PanMovesTheDataWithTheMouse) {
    Camera camera;
    const glm::dvec3 point = kUnitCube.center();
    const glm::dvec2 before = screenPosition(camera, point);
    panCamera(camera, {30.0, -20.0}, kUnitCube, kViewport);
    const glm::dvec2 after = screenPosition(camera, point);
    // The target's depth is where world units per pixel are measured, and the point is the target.
    EXPECT_NEAR(after.x - before.x, 30.0, 1e-6);
    EXPECT_NEAR(after.y - before.y, -20.0, 1e-6);
}

TEST(CameraController, ZoomScalesTheDistance) {
    Camera camera;
    camera.pose = OrbitCamera{glm::dvec3(0.5), 4.0, 0.0, 0.0};
    zoomCamera(camera, 2.0, kUnitCube, kViewport);
    EXPECT_NEAR(*std::get<OrbitCamera>(camera.pose).distance, 4.0 * kZoomFactorPerNotch * kZoomFactorPerNotch, 1e-12);
}

TEST(CameraController, LookAtCamerasBecomeTheSameOrbit) {
    Camera camera;
    camera.pose = LookAtCamera{{0.5, 0.5, 3.5}, {0.5, 0.5, 0.5}, {0.0, 1.0, 0.0}};
    const OrbitCamera orbit = asOrbit(camera);
    EXPECT_NEAR(orbit.azimuthDeg, 0.0, 1e-12);
    EXPECT_NEAR(orbit.elevationDeg, 0.0, 1e-12);
    EXPECT_NEAR(*orbit.distance, 3.0, 1e-12);
    Camera converted = camera;
    converted.pose = orbit;
    const View a = resolveView(camera, kUnitCube, kViewport.x, kViewport.y);
    const View b = resolveView(converted, kUnitCube, kViewport.x, kViewport.y);
    EXPECT_NEAR(glm::distance(a.eye, b.eye), 0.0, 1e-12);
}

TEST(CameraController, FitForgetsTargetAndDistanceButKeepsTheDirection) {
    Camera camera;
    camera.pose = OrbitCamera{glm::dvec3(3.0), 50.0, 42.0, -12.0};
    const OrbitCamera fitted = std::get<OrbitCamera>(fitCameraToData(camera).pose);
    EXPECT_FALSE(fitted.target.has_value());
    EXPECT_FALSE(fitted.distance.has_value());
    EXPECT_EQ(fitted.azimuthDeg, 42.0);
    EXPECT_EQ(fitted.elevationDeg, -12.0);
}

}  // namespace
