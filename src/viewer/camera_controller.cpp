// Orbit, pan and zoom in terms of the orbit camera's parameters.
#include "camera_controller.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tstyles::viewer {
namespace {

constexpr double kMaxElevationDeg = 89.0;
constexpr double kRadiansToDegrees = 180.0 / std::numbers::pi;

// The orbit camera with target and distance as the renderer resolves them for this viewport.
OrbitCamera explicitOrbit(const Camera& camera, const Bounds& bounds, glm::ivec2 viewport) {
    OrbitCamera orbit = asOrbit(camera);
    Camera resolved = camera;
    resolved.pose = orbit;
    const View view = resolveView(resolved, bounds, viewport.x, viewport.y);
    orbit.target = view.target;
    orbit.distance = glm::distance(view.eye, view.target);
    return orbit;
}

}  // namespace

OrbitCamera asOrbit(const Camera& camera) {
    if (const auto* orbit = std::get_if<OrbitCamera>(&camera.pose)) return *orbit;
    const auto& lookAt = std::get<LookAtCamera>(camera.pose);
    const glm::dvec3 offset = lookAt.eye - lookAt.target;
    const double distance = glm::length(offset);
    OrbitCamera orbit;
    orbit.target = lookAt.target;
    orbit.distance = distance;
    orbit.azimuthDeg = std::atan2(offset.x, offset.z) * kRadiansToDegrees;
    orbit.elevationDeg = std::asin(std::clamp(offset.y / distance, -1.0, 1.0)) * kRadiansToDegrees;
    return orbit;
}

void orbitCamera(Camera& camera, glm::dvec2 pixelDelta) {
    OrbitCamera orbit = asOrbit(camera);
    // Azimuth kept in (-180, 180] so that saved scenes do not accumulate whole turns.
    double azimuth = std::remainder(orbit.azimuthDeg - pixelDelta.x * kOrbitDegreesPerPixel, 360.0);
    if (azimuth <= -180.0) azimuth += 360.0;
    orbit.azimuthDeg = azimuth;
    orbit.elevationDeg =
        std::clamp(orbit.elevationDeg + pixelDelta.y * kOrbitDegreesPerPixel, -kMaxElevationDeg, kMaxElevationDeg);
    camera.pose = orbit;
}

void panCamera(Camera& camera, glm::dvec2 pixelDelta, const Bounds& bounds, glm::ivec2 viewport) {
    OrbitCamera orbit = explicitOrbit(camera, bounds, viewport);
    Camera resolved = camera;
    resolved.pose = orbit;
    const View view = resolveView(resolved, bounds, viewport.x, viewport.y);
    // World units per pixel at the target's depth (the same for both projections: an orthographic
    // view shows the height a perspective one would show at the target).
    const double worldPerPixel =
        2.0 * *orbit.distance * std::tan(0.5 * camera.fovDeg * std::numbers::pi / 180.0) / double(viewport.y);
    const glm::dvec3 right{view.viewMatrix[0][0], view.viewMatrix[1][0], view.viewMatrix[2][0]};
    const glm::dvec3 up{view.viewMatrix[0][1], view.viewMatrix[1][1], view.viewMatrix[2][1]};
    // Screen y grows downward; moving the target against the mouse makes the data follow it.
    orbit.target = *orbit.target - right * (pixelDelta.x * worldPerPixel) + up * (pixelDelta.y * worldPerPixel);
    camera.pose = orbit;
}

void zoomCamera(Camera& camera, double notches, const Bounds& bounds, glm::ivec2 viewport) {
    OrbitCamera orbit = explicitOrbit(camera, bounds, viewport);
    const double scale = std::max(glm::length(bounds.size()), 1e-6);
    orbit.distance = std::clamp(*orbit.distance * std::pow(kZoomFactorPerNotch, notches), 1e-3 * scale, 1e3 * scale);
    camera.pose = orbit;
}

Camera frameExplicitly(const Camera& camera, const Bounds& framed, glm::ivec2 viewport) {
    const auto* orbit = std::get_if<OrbitCamera>(&camera.pose);
    if (orbit == nullptr || (orbit->target && orbit->distance)) return camera;
    Camera framedCamera = camera;
    framedCamera.pose = explicitOrbit(camera, framed, viewport);
    return framedCamera;
}

Camera fitCameraToData(const Camera& camera) {
    Camera fitted = camera;
    OrbitCamera orbit = asOrbit(camera);
    orbit.target.reset();
    orbit.distance.reset();
    fitted.pose = orbit;
    return fitted;
}

}  // namespace tstyles::viewer
