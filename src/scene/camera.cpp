// Resolves a camera as the user states it (orbit or look-at) into eye, matrices and clip planes for
// a series' bounds. Double precision throughout; the renderer narrows to float at upload.
#include "tstyles/scene/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

namespace tstyles {
namespace {

constexpr double degreesToRadians = std::numbers::pi / 180.0;

// Half the diagonal of the bounds: the radius of the sphere that holds the whole series. A series
// without extent (a single sample) still needs a finite scale to place the camera and clip planes.
double boundingRadius(const Bounds& bounds) {
    const double radius = 0.5 * glm::length(bounds.size());
    return (std::isfinite(radius) && radius > 0.0) ? radius : 1.0;
}

// The distance at which the bounding sphere fits the narrower of the two fields of view, with a
// 10 % margin so that the silhouette does not touch the image border.
double framingDistance(double radius, double fovYRadians, double aspect) {
    const double fovXRadians = 2.0 * std::atan(aspect * std::tan(0.5 * fovYRadians));
    const double narrowest = std::min(fovYRadians, fovXRadians);
    return 1.1 * radius / std::sin(0.5 * narrowest);
}

struct Pose {
    glm::dvec3 eye;
    glm::dvec3 target;
    glm::dvec3 up;
};

Pose orbitPose(const OrbitCamera& orbit, const Bounds& bounds, double fovYRadians, double aspect) {
    const glm::dvec3 target = orbit.target.value_or(bounds.center());
    const double distance =
        orbit.distance.value_or(framingDistance(boundingRadius(bounds), fovYRadians, aspect));
    const double azimuth = orbit.azimuthDeg * degreesToRadians;
    const double elevation = orbit.elevationDeg * degreesToRadians;
    const glm::dvec3 horizontal{std::sin(azimuth), 0.0, std::cos(azimuth)};
    const glm::dvec3 offset{std::cos(elevation) * horizontal.x, std::sin(elevation),
                            std::cos(elevation) * horizontal.z};

    glm::dvec3 up{0.0, 1.0, 0.0};
    // Straight above or below the target, world up is parallel to the view direction. Use the up
    // vector that the view approaches as the elevation nears ±90°, so the image does not spin.
    if (std::abs(std::cos(elevation)) < 1e-9) {
        up = (elevation > 0.0 ? -1.0 : 1.0) * horizontal;
    }
    return {target + distance * offset, target, up};
}

Pose lookAtPose(const LookAtCamera& lookAt) { return {lookAt.eye, lookAt.target, lookAt.up}; }

}  // namespace

View resolveView(const Camera& camera, const Bounds& seriesBounds, int width, int height) {
    return resolveView(camera, seriesBounds, seriesBounds, width, height);
}

View resolveView(const Camera& camera, const Bounds& framed, const Bounds& seriesBounds, int width, int height) {
    const double aspect = double(std::max(width, 1)) / double(std::max(height, 1));
    const double fovYRadians = camera.fovDeg * degreesToRadians;
    const Pose pose = std::holds_alternative<OrbitCamera>(camera.pose)
                          ? orbitPose(std::get<OrbitCamera>(camera.pose), framed, fovYRadians, aspect)
                          : lookAtPose(std::get<LookAtCamera>(camera.pose));

    View view;
    view.eye = pose.eye;
    view.target = pose.target;
    view.up = pose.up;
    view.fovDeg = camera.fovDeg;
    view.projection = camera.projection;
    view.viewMatrix = glm::lookAt(pose.eye, pose.target, pose.up);

    // Clip planes hug the bounding sphere, measured from the series' centre rather than from the
    // target: a look-at target away from the data must not clip the data. Near never reaches 0,
    // which would waste the depth buffer's precision.
    const double radius = boundingRadius(seriesBounds);
    const double centreDistance = glm::distance(pose.eye, seriesBounds.center());
    view.farPlane = centreDistance + 2.0 * radius;
    view.nearPlane = std::max(centreDistance - 2.0 * radius, 1e-3 * (centreDistance + radius));

    if (camera.projection == Projection::Perspective) {
        view.projectionMatrix = glm::perspective(fovYRadians, aspect, view.nearPlane, view.farPlane);
    } else {
        // The height the perspective view would show at the target, so switching keeps the framing.
        const double halfHeight = glm::distance(pose.eye, pose.target) * std::tan(0.5 * fovYRadians);
        const double halfWidth = halfHeight * aspect;
        view.projectionMatrix =
            glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, view.nearPlane, view.farPlane);
    }
    return view;
}

std::string toString(Projection projection) {
    return projection == Projection::Perspective ? "perspective" : "orthographic";
}

std::optional<Projection> projectionFromString(const std::string& name) {
    if (name == "perspective") return Projection::Perspective;
    if (name == "orthographic") return Projection::Orthographic;
    return std::nullopt;
}

std::vector<std::string> projectionNames() {
    return {toString(Projection::Perspective), toString(Projection::Orthographic)};
}

std::string toString(Framing framing) { return framing == Framing::Series ? "series" : "visible"; }

std::optional<Framing> framingFromString(const std::string& name) {
    if (name == "series") return Framing::Series;
    if (name == "visible") return Framing::Visible;
    return std::nullopt;
}

std::vector<std::string> framingNames() { return {toString(Framing::Series), toString(Framing::Visible)}; }

}  // namespace tstyles
