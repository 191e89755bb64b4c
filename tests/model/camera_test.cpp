// Cameras resolved against known bounds: orbit positions, automatic framing, projections, clip planes.
#include <array>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "tstyles/scene/camera.h"

namespace {

using tstyles::Bounds;
using tstyles::Camera;
using tstyles::LookAtCamera;
using tstyles::OrbitCamera;
using tstyles::Projection;
using tstyles::View;

constexpr double tolerance = 1e-9;  // a few trigonometric functions in double precision

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

Camera orbitCamera(const OrbitCamera& orbit, Projection projection = Projection::Perspective) {
    Camera camera;
    camera.pose = orbit;
    camera.projection = projection;
    return camera;
}

std::array<glm::dvec3, 8> cornersOf(const Bounds& bounds) {
    std::array<glm::dvec3, 8> corners;
    for (int i = 0; i < 8; ++i) {
        corners[i] = {(i & 1) ? bounds.upper.x : bounds.lower.x, (i & 2) ? bounds.upper.y : bounds.lower.y,
                      (i & 4) ? bounds.upper.z : bounds.lower.z};
    }
    return corners;
}

glm::dvec3 toNdc(const View& view, const glm::dvec3& world) {
    const glm::dvec4 clip = view.projectionMatrix * view.viewMatrix * glm::dvec4(world, 1.0);
    return glm::dvec3(clip) / clip.w;
}

TEST(CameraOrbit, AzimuthNinetyPutsTheEyeOnPlusX) {
    const Camera camera = orbitCamera({glm::dvec3(1.0, 2.0, 3.0), 4.0, 90.0, 0.0});
    const View view = tstyles::resolveView(camera, Bounds{}, 100, 100);
    expectNear(view.eye, {5.0, 2.0, 3.0});
    expectNear(view.target, {1.0, 2.0, 3.0});
}

TEST(CameraOrbit, AzimuthZeroLooksDownMinusZ) {
    const Camera camera = orbitCamera({glm::dvec3(0.0), 2.0, 0.0, 0.0});
    const View view = tstyles::resolveView(camera, Bounds{{-1, -1, -1}, {1, 1, 1}}, 100, 100);
    expectNear(view.eye, {0.0, 0.0, 2.0});
    // The target lies straight ahead in eye space, which looks down its own -z.
    expectNear(glm::dvec3(view.viewMatrix * glm::dvec4(0.0, 0.0, 0.0, 1.0)), {0.0, 0.0, -2.0});
}

TEST(CameraOrbit, ElevationLiftsTheEyeAndStaysValidStraightAbove) {
    const Bounds bounds{{-1, -1, -1}, {1, 1, 1}};
    const View lifted = tstyles::resolveView(orbitCamera({glm::dvec3(0.0), 2.0, 0.0, 30.0}), bounds, 64, 64);
    expectNear(lifted.eye, {0.0, 1.0, 2.0 * std::cos(std::numbers::pi / 6.0)});

    for (double elevation : {90.0, -90.0}) {
        const View view =
            tstyles::resolveView(orbitCamera({glm::dvec3(0.0), 2.0, 45.0, elevation}), bounds, 64, 64);
        expectNear(view.eye, {0.0, elevation > 0 ? 2.0 : -2.0, 0.0});
        for (int column = 0; column < 4; ++column) {
            for (int row = 0; row < 4; ++row) {
                EXPECT_TRUE(std::isfinite(view.viewMatrix[column][row])) << "elevation " << elevation;
            }
        }
        expectNear(glm::dvec3(view.viewMatrix * glm::dvec4(0.0, 0.0, 0.0, 1.0)), {0.0, 0.0, -2.0});
    }
}

TEST(CameraOrbit, TheDefaultTargetIsTheCentreOfTheBounds) {
    const Bounds bounds{{0.0, 0.0, 0.0}, {2.0, 4.0, 6.0}};
    const View view = tstyles::resolveView(Camera{}, bounds, 512, 512);
    expectNear(view.target, {1.0, 2.0, 3.0});
}

TEST(CameraOrbit, TheDefaultDistanceFramesTheBoundingSphere) {
    const Bounds bounds{{0.0, 0.0, 0.0}, {1.0, 0.8, 1.0}};
    const double radius = 0.5 * glm::length(bounds.size());
    const View square = tstyles::resolveView(orbitCamera({}), bounds, 512, 512);
    const double fovY = 30.0 * std::numbers::pi / 180.0;
    EXPECT_NEAR(glm::distance(square.eye, square.target), 1.1 * radius / std::sin(0.5 * fovY), tolerance);

    // Every corner inside the image, whatever the direction, aspect and projection.
    for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
        for (auto [width, height] : {std::pair{512, 512}, {1920, 1080}, {300, 900}}) {
            for (double azimuth : {0.0, 30.0, 135.0, 270.0}) {
                for (double elevation : {-90.0, -45.0, 0.0, 20.0, 90.0}) {
                    const Camera camera =
                        orbitCamera({std::nullopt, std::nullopt, azimuth, elevation}, projection);
                    const View view = tstyles::resolveView(camera, bounds, width, height);
                    for (const glm::dvec3& corner : cornersOf(bounds)) {
                        const glm::dvec3 ndc = toNdc(view, corner);
                        EXPECT_LE(std::abs(ndc.x), 1.0) << width << "x" << height << " az " << azimuth;
                        EXPECT_LE(std::abs(ndc.y), 1.0) << width << "x" << height << " el " << elevation;
                        EXPECT_LE(std::abs(ndc.z), 1.0) << "corner outside the clip planes";
                    }
                }
            }
        }
    }
}

TEST(Camera, LookAtIsUsedAsGiven) {
    Camera camera;
    camera.pose = LookAtCamera{{1.0, 2.0, 3.0}, {1.0, 2.0, 0.0}, {0.0, 1.0, 0.0}};
    const View view = tstyles::resolveView(camera, Bounds{{0, 0, 0}, {1, 1, 1}}, 100, 100);
    expectNear(view.eye, {1.0, 2.0, 3.0});
    expectNear(view.target, {1.0, 2.0, 0.0});
    expectNear(glm::dvec3(view.viewMatrix * glm::dvec4(1.0, 2.0, 0.0, 1.0)), {0.0, 0.0, -3.0});
}

TEST(Camera, OrthographicShowsTheHeightTheFieldOfViewSpansAtTheTarget) {
    Camera camera;
    camera.pose = LookAtCamera{{0.0, 0.0, 10.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};
    camera.projection = Projection::Orthographic;
    camera.fovDeg = 40.0;
    const View view = tstyles::resolveView(camera, Bounds{{-1, -1, -1}, {1, 1, 1}}, 200, 100);
    const double halfHeight = 10.0 * std::tan(20.0 * std::numbers::pi / 180.0);
    // glm::ortho scales x by 1 / half-width and y by 1 / half-height.
    EXPECT_NEAR(view.projectionMatrix[1][1], 1.0 / halfHeight, tolerance);
    EXPECT_NEAR(view.projectionMatrix[0][0], 1.0 / (2.0 * halfHeight), tolerance);
    EXPECT_NEAR(toNdc(view, {0.0, halfHeight, 0.0}).y, 1.0, tolerance);
}

TEST(Camera, PerspectiveUsesTheFieldOfViewAndAspect) {
    Camera camera;
    camera.fovDeg = 50.0;
    const View view = tstyles::resolveView(camera, Bounds{{0, 0, 0}, {1, 1, 1}}, 400, 200);
    const glm::dmat4 expected =
        glm::perspective(50.0 * std::numbers::pi / 180.0, 2.0, view.nearPlane, view.farPlane);
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            EXPECT_NEAR(view.projectionMatrix[column][row], expected[column][row], tolerance);
        }
    }
}

TEST(Camera, ClipPlanesHugTheBoundingSphere) {
    const Bounds bounds{{-1, -1, -1}, {1, 1, 1}};
    const double radius = std::sqrt(3.0);
    const View distant = tstyles::resolveView(orbitCamera({std::nullopt, 10.0, 0.0, 0.0}), bounds, 64, 64);
    EXPECT_NEAR(distant.nearPlane, 10.0 - 2.0 * radius, tolerance);
    EXPECT_NEAR(distant.farPlane, 10.0 + 2.0 * radius, tolerance);

    // Inside the sphere the near plane stays positive, a small fraction of the scene's depth.
    const View inside = tstyles::resolveView(orbitCamera({std::nullopt, 0.5, 0.0, 0.0}), bounds, 64, 64);
    EXPECT_NEAR(inside.nearPlane, 1e-3 * (0.5 + radius), tolerance);
    EXPECT_GT(inside.farPlane, inside.nearPlane);
}

TEST(Camera, ProjectionNamesReadBack) {
    for (const std::string& name : tstyles::projectionNames()) {
        const auto projection = tstyles::projectionFromString(name);
        ASSERT_TRUE(projection.has_value()) << name;
        EXPECT_EQ(tstyles::toString(*projection), name);
    }
    EXPECT_FALSE(tstyles::projectionFromString("fisheye").has_value());
}

}  // namespace
