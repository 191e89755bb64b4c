// A camera as the user states it (orbit or look-at) and the view it resolves to for a given series.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

enum class Projection { Perspective, Orthographic };

std::string toString(Projection projection);  // "perspective", "orthographic"
std::optional<Projection> projectionFromString(const std::string& name);
std::vector<std::string> projectionNames();

// Orbit around a target; y is up. Azimuth turns from +z toward +x, elevation lifts from the xz-plane.
// A missing target is the centre of the series' bounds; a missing distance frames the whole series.
struct OrbitCamera {
    std::optional<glm::dvec3> target;
    std::optional<double> distance;
    double azimuthDeg = 30.0;
    double elevationDeg = 20.0;
    bool operator==(const OrbitCamera&) const = default;
};

struct LookAtCamera {
    glm::dvec3 eye{0.0, 0.0, 5.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    bool operator==(const LookAtCamera&) const = default;
};

// What an orbit camera without target or distance frames: the bounds of the whole series, or of
// the part the STF leaves visible (visibleBounds in tstyles/scene/visible_bounds.h).
enum class Framing { Series, Visible };

std::string toString(Framing framing);  // "series", "visible"
std::optional<Framing> framingFromString(const std::string& name);
std::vector<std::string> framingNames();

struct Camera {
    std::variant<OrbitCamera, LookAtCamera> pose = OrbitCamera{};
    Framing framing = Framing::Series;
    // Vertical field of view. An orthographic camera shows the height that this field of view
    // spans at the target's distance, so switching projection keeps the framing.
    double fovDeg = 30.0;
    Projection projection = Projection::Perspective;
    bool operator==(const Camera&) const = default;
};

// The camera resolved against a series: everything the renderer needs.
struct View {
    glm::dvec3 eye{0.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovDeg = 30.0;
    Projection projection = Projection::Perspective;
    glm::dmat4 viewMatrix{1.0};
    glm::dmat4 projectionMatrix{1.0};
    double nearPlane = 0.01;
    double farPlane = 100.0;
};

View resolveView(const Camera& camera, const Bounds& seriesBounds, int width, int height);
// The same, with the bounds an automatic orbit frames (`framed`, the visible part) apart from the
// bounds the clip planes must hold (`all`, the whole series).
View resolveView(const Camera& camera, const Bounds& framed, const Bounds& all, int width, int height);

}  // namespace tstyles
