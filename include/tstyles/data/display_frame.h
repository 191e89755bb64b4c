// The display frame: how a series' world axes become the axes the camera sees. A turn that puts the
// file's "up" on world y (surface on top, head up), and a scale per axis (physical proportions,
// each axis the same length, a map with vertical exaggeration). Chosen from what the file says its
// axes mean (docs/automatic-scene.md) or stated in the scene; applied to the series once, before
// upload, so the renderer sees an ordinary series. GL-free.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

// A data axis and a sign, as scenes spell it: "+x", "-z".
struct SignedAxis {
    int axis = 0;  // 0, 1, 2: the series' world x, y, z
    bool negated = false;
    bool operator==(const SignedAxis&) const = default;
};

std::string toString(const SignedAxis& axis);
std::optional<SignedAxis> signedAxisFromString(const std::string& text);

// The signed permutation that shows data axis rows[d] along display axis d (determinant -1 when the
// rows make a left-handed frame, which scenes refuse).
glm::dmat3 rotationOf(const std::array<SignedAxis, 3>& rows);

// Which data axis becomes display x, y (up) and z (toward a camera at azimuth 0).
struct Orientation {
    enum class Mode { Data, Auto, Axes } mode = Mode::Data;  // Data: as stored (the axes unchanged)
    std::array<SignedAxis, 3> axes{SignedAxis{0}, SignedAxis{1}, SignedAxis{2}};  // Mode::Axes
    bool operator==(const Orientation&) const = default;
};

// How long a unit of each axis is drawn.
struct Aspect {
    // Physical: each axis in its own unit (lengths in one unit: km and m alike); Cubic: each axis
    // stretched to the same length; Scale: `scale` per display axis; Auto: physical when the axes
    // share a kind of unit and none is over ten times another, else a map (docs/automatic-scene.md).
    enum class Mode { Physical, Cubic, Scale, Auto } mode = Mode::Physical;
    glm::dvec3 scale{1.0};  // Mode::Scale, per display axis (after the orientation)
    bool operator==(const Aspect&) const = default;
};

struct DisplaySettings {
    Orientation orientation;
    Aspect aspect;
    // Multiplies the display's vertical (y) scale; none: automatic (1, or for a map the factor that
    // makes the height a quarter of the width).
    std::optional<double> verticalExaggeration = 1.0;
    bool operator==(const DisplaySettings&) const = default;
};

// What the settings resolve to for one series: display = scale * (rotation * world).
struct DisplayFrame {
    glm::dmat3 rotation{1.0};  // a signed permutation with determinant +1
    glm::dvec3 scale{1.0};     // per display axis
    double verticalExaggeration = 1.0;  // already part of scale.y; kept for messages
    // For `tstyles info` and the viewer: what was chosen and why, one line each.
    std::vector<std::string> explanation;

    bool isIdentity() const { return rotation == glm::dmat3(1.0) && scale == glm::dvec3(1.0); }
    // Display position of a world (data) position.
    glm::dvec3 toDisplay(const glm::dvec3& world) const { return scale * (rotation * world); }
    // World (data) position of a display position: the inverse of toDisplay.
    glm::dvec3 toWorld(const glm::dvec3& display) const { return glm::transpose(rotation) * (display / scale); }
};

DisplayFrame chooseDisplayFrame(const DisplaySettings& settings, const Series& series);

// The series in display coordinates: placements turned and scaled, grid spacings scaled, and its
// axis descriptions in display order. Rotations and a uniform scale work for every grid; a scale
// that differs between axes needs each time-step's grid axes to lie along display axes (readers'
// grids do) and rectilinear or structured grids: anything else is an InputError naming the
// time-step and what to use instead.
Series applyDisplayFrame(Series series, const DisplayFrame& frame);

// A display position of `shown` (a series that applyDisplayFrame turned with `frame`) in the file's
// own coordinates, as `tstyles info` lists them and `probe --at` takes them (the frame undone, the
// negated axes flipped back: fileCoordinatesOf of the series as read); and the inverse.
glm::dvec3 fileCoordinatesOfShown(const Series& shown, const DisplayFrame& frame, const glm::dvec3& display);
glm::dvec3 shownCoordinatesOfFile(const Series& shown, const DisplayFrame& frame, const glm::dvec3& file);

}  // namespace tstyles
