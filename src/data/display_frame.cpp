// Choosing and applying the display frame (display_frame.h; the rules: docs/automatic-scene.md).
#include "tstyles/data/display_frame.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include <glm/gtc/quaternion.hpp>

#include "axis_units.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};
// Beyond this ratio of the longest to the shortest extent, physical proportions show a thin slab.
constexpr double kLargestPhysicalRatio = 10.0;
// A map's height is made this fraction of its width.
constexpr double kMapHeightFraction = 0.25;

std::string number(double value, int digits = 3) {
    std::ostringstream text;
    text << std::setprecision(digits) << value;
    return text.str();
}

// Where each known direction goes on screen: display axis and sign. North points away from a
// camera at azimuth 0 (north up in a view from the south), east to the right; the patient faces a
// camera at azimuth 0, so their left is on the image's right.
std::optional<SignedAxis> displayAxisOf(AxisDirection direction) {
    switch (direction) {
        case AxisDirection::East: case AxisDirection::Left: return SignedAxis{0, false};
        case AxisDirection::West: case AxisDirection::Right: return SignedAxis{0, true};
        case AxisDirection::Up: case AxisDirection::Superior: return SignedAxis{1, false};
        case AxisDirection::Down: case AxisDirection::Inferior: return SignedAxis{1, true};
        case AxisDirection::South: case AxisDirection::Anterior: return SignedAxis{2, false};
        case AxisDirection::North: case AxisDirection::Posterior: return SignedAxis{2, true};
        case AxisDirection::Unknown: return std::nullopt;
    }
    return std::nullopt;
}

std::array<SignedAxis, 3> rowsOf(const glm::dmat3& rotation) {
    std::array<SignedAxis, 3> rows{};
    for (int display = 0; display < 3; ++display)
        for (int data = 0; data < 3; ++data)
            if (rotation[data][display] != 0.0) rows[std::size_t(display)] = {data, rotation[data][display] < 0.0};
    return rows;
}

std::string axisLabel(const Series& series, int axis) {
    const SpatialAxis& described = series.axes[std::size_t(axis)];
    std::string label = described.name.empty() ? kAxisNames[axis] : described.name;
    if (described.direction != AxisDirection::Unknown) label += ", " + toString(described.direction);
    return label;
}

// The automatic turn: every axis whose direction the file gives goes where displayAxisOf says; the
// others fill the display axes left over, in order; a left-handed result mirrors display x.
// The data axis whose extent (in a unit shared by all three: lengths in m and km alike, or voxels)
// is over kLargestPhysicalRatio times thinner than the widest; none where the units differ in kind.
std::optional<int> extremelyThinAxis(const Series& series) {
    const Bounds bounds = series.worldBounds();
    std::array<AxisUnit, 3> units;
    for (int axis = 0; axis < 3; ++axis) units[std::size_t(axis)] = parseAxisUnit(series.axes[std::size_t(axis)].unit);
    if (!units[0].sameKind(units[1]) || !units[1].sameKind(units[2])) return std::nullopt;
    glm::dvec3 extent;
    for (int axis = 0; axis < 3; ++axis) extent[axis] = bounds.size()[axis] * units[std::size_t(axis)].toBase;
    int thin = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (extent[axis] < extent[thin]) thin = axis;
    const double widest = std::max({extent.x, extent.y, extent.z});
    if (!(extent[thin] > 0.0) || widest <= kLargestPhysicalRatio * extent[thin]) return std::nullopt;
    return thin;
}

glm::dmat3 automaticRotation(const Series& series, std::vector<std::string>& explanation) {
    std::array<std::optional<SignedAxis>, 3> rows;
    std::array<bool, 3> placed{};
    for (int data = 0; data < 3; ++data)
        if (const auto target = displayAxisOf(series.axes[std::size_t(data)].direction);
            target && !rows[std::size_t(target->axis)]) {
            rows[std::size_t(target->axis)] = SignedAxis{data, target->negated};
            placed[std::size_t(data)] = true;
        }
    const bool noMeaning = std::none_of(placed.begin(), placed.end(), [](bool p) { return p; });
    const auto thin = noMeaning ? extremelyThinAxis(series) : std::nullopt;
    if (thin) {
        // Nothing says which way is up, and one axis is far thinner than the others: it goes up, so
        // that the vertical exaggeration thickens it and the camera looks at the large face.
        rows[1] = SignedAxis{*thin, false};
        placed[std::size_t(*thin)] = true;
        explanation.push_back("up: " + axisLabel(series, *thin) + ", the thinnest axis (over " +
                              number(kLargestPhysicalRatio) + " times thinner than the widest)");
    }
    for (int display = 0; display < 3; ++display) {
        if (rows[std::size_t(display)]) continue;
        const int data = int(std::find(placed.begin(), placed.end(), false) - placed.begin());
        rows[std::size_t(display)] = SignedAxis{data, false};
        placed[std::size_t(data)] = true;
    }
    std::array<SignedAxis, 3> chosen{*rows[0], *rows[1], *rows[2]};
    if (thin && glm::determinant(rotationOf(chosen)) < 0.0) {
        // Moving the thin axis up swapped two axes, not the file's handedness: the axis toward the
        // viewer turns, so that a map seen from above keeps the file's x to the right and its y up
        // the picture (a TIFF's row 0 at the top, as Fiji shows it), not turned half round.
        chosen[2].negated = !chosen[2].negated;
        explanation.push_back("toward the viewer: -" + axisLabel(series, chosen[2].axis) +
                              ", so that seen from above " + axisLabel(series, chosen[0].axis) + " runs right and " +
                              axisLabel(series, chosen[2].axis) + " up the picture");
    } else if (glm::determinant(rotationOf(chosen)) < 0.0) {
        chosen[0].negated = !chosen[0].negated;
        explanation.push_back("the file's axes are left-handed: display x runs against " +
                              axisLabel(series, chosen[0].axis));
    }
    return rotationOf(chosen);
}

struct DisplayAxes {
    std::array<AxisUnit, 3> units;
    glm::dvec3 extent{1.0};       // display extents before scaling
    glm::dvec3 centre{0.0};       // display centre before scaling
};

DisplayAxes displayAxes(const Series& series, const glm::dmat3& rotation) {
    DisplayAxes axes;
    const Bounds bounds = series.worldBounds();
    const std::array<SignedAxis, 3> rows = rowsOf(rotation);
    for (int display = 0; display < 3; ++display) {
        const int data = rows[std::size_t(display)].axis;
        axes.units[std::size_t(display)] = parseAxisUnit(series.axes[std::size_t(data)].unit);
        axes.extent[display] = std::max(bounds.size()[data], 1e-12);
        axes.centre[display] = bounds.center()[data];
    }
    return axes;
}

bool shareKind(const DisplayAxes& axes) {
    return axes.units[0].sameKind(axes.units[1]) && axes.units[1].sameKind(axes.units[2]);
}

// Each axis in its own unit; lengths (or pressures, or angles) of different units in the smallest
// of them (km and m in m), so that data in one unit keeps its coordinates.
glm::dvec3 physicalScale(const DisplayAxes& axes) {
    if (!shareKind(axes)) return glm::dvec3(1.0);
    const glm::dvec3 toBase{axes.units[0].toBase, axes.units[1].toBase, axes.units[2].toBase};
    return toBase / std::min({toBase.x, toBase.y, toBase.z});
}

glm::dvec3 cubicScale(const DisplayAxes& axes) {
    const double longest = std::max({axes.extent.x, axes.extent.y, axes.extent.z});
    return glm::dvec3(longest) / axes.extent;
}

std::string unitText(const AxisUnit& unit) { return unit.text.empty() ? "no unit" : unit.text; }

bool isGeographicMap(const Series& series, const glm::dmat3& rotation, const DisplayAxes& axes) {
    const std::array<SignedAxis, 3> rows = rowsOf(rotation);
    const AxisDirection x = series.axes[std::size_t(rows[0].axis)].direction;
    const AxisDirection z = series.axes[std::size_t(rows[2].axis)].direction;
    const bool eastWest = x == AxisDirection::East || x == AxisDirection::West;
    const bool northSouth = z == AxisDirection::North || z == AxisDirection::South;
    return eastWest && northSouth && axes.units[0].kind == UnitKind::Angle && axes.units[2].kind == UnitKind::Angle;
}

// The horizontal axes (display x and z) of a map, and the vertical's scale before exaggeration.
glm::dvec3 mapScale(const Series& series, const glm::dmat3& rotation, const DisplayAxes& axes,
                    std::vector<std::string>& explanation) {
    glm::dvec3 scale(1.0);
    if (isGeographicMap(series, rotation, axes)) {
        const double latitude = std::clamp(std::abs(axes.centre.z), 0.0, 89.0);
        scale.x = std::cos(latitude * std::numbers::pi / 180.0) * axes.units[0].toBase;
        scale.z = axes.units[2].toBase;
        explanation.push_back("horizontal: degrees, east-west by cos(" + number(latitude) + " deg) = " +
                              number(scale.x) + " so a degree east is as long as one north at the centre");
    } else if (axes.units[0].sameKind(axes.units[2])) {
        scale.x = axes.units[0].toBase;
        scale.z = axes.units[2].toBase;
        explanation.push_back("horizontal: x and z in " + unitText(axes.units[0]) + ", physical");
    } else {
        const double longest = std::max(axes.extent.x, axes.extent.z);
        scale.x = longest / axes.extent.x;
        scale.z = longest / axes.extent.z;
        explanation.push_back("horizontal: x (" + unitText(axes.units[0]) + ") and z (" + unitText(axes.units[2]) +
                              ") stretched to the same length");
    }
    // A vertical in the horizontal's kind of unit keeps its proportion; metres under degrees count
    // a degree as its length along a meridian.
    const AxisUnit& vertical = axes.units[1];
    if (vertical.sameKind(axes.units[2]))
        scale.y = vertical.toBase;
    else if (vertical.kind == UnitKind::Length && axes.units[2].kind == UnitKind::Angle)
        scale.y = vertical.toBase / kMetresPerDegreeOfLatitude;
    return scale;
}

double roundToTwoDigits(double value) {
    const double magnitude = std::pow(10.0, std::floor(std::log10(value)) - 1.0);
    return std::round(value / magnitude) * magnitude;
}

}  // namespace

glm::dmat3 rotationOf(const std::array<SignedAxis, 3>& rows) {
    glm::dmat3 rotation(0.0);
    for (int display = 0; display < 3; ++display)
        rotation[rows[std::size_t(display)].axis][display] = rows[std::size_t(display)].negated ? -1.0 : 1.0;
    return rotation;  // glm is column-major: rotation[column][row]
}

std::string toString(const SignedAxis& axis) { return std::string(axis.negated ? "-" : "+") + kAxisNames[axis.axis]; }

std::optional<SignedAxis> signedAxisFromString(const std::string& text) {
    if (text.size() != 2 || (text[0] != '+' && text[0] != '-')) return std::nullopt;
    const int axis = text[1] == 'x' ? 0 : text[1] == 'y' ? 1 : text[1] == 'z' ? 2 : -1;
    if (axis < 0) return std::nullopt;
    return SignedAxis{axis, text[0] == '-'};
}

DisplayFrame chooseDisplayFrame(const DisplaySettings& settings, const Series& series) {
    DisplayFrame frame;
    switch (settings.orientation.mode) {
        case Orientation::Mode::Data: break;
        case Orientation::Mode::Axes: frame.rotation = rotationOf(settings.orientation.axes); break;
        case Orientation::Mode::Auto: frame.rotation = automaticRotation(series, frame.explanation); break;
    }
    const std::array<SignedAxis, 3> rows = rowsOf(frame.rotation);
    frame.explanation.insert(frame.explanation.begin(),
                             "orientation: right = " + toString(rows[0]) + " (" + axisLabel(series, rows[0].axis) +
                                 "), up = " + toString(rows[1]) + " (" + axisLabel(series, rows[1].axis) +
                                 "), toward the viewer = " + toString(rows[2]) + " (" +
                                 axisLabel(series, rows[2].axis) + ")");

    const DisplayAxes axes = displayAxes(series, frame.rotation);
    Aspect::Mode mode = settings.aspect.mode;
    bool map = false;
    if (mode == Aspect::Mode::Auto) {
        const glm::dvec3 physical = axes.extent * physicalScale(axes);
        const double ratio = std::max({physical.x, physical.y, physical.z}) / std::min({physical.x, physical.y, physical.z});
        if (shareKind(axes) && ratio <= kLargestPhysicalRatio) {
            mode = Aspect::Mode::Physical;
            frame.explanation.push_back("aspect: physical (the axes share a kind of unit, " + unitText(axes.units[0]) +
                                        ", and the longest is " + number(ratio) + " times the shortest)");
        } else {
            map = true;
            frame.explanation.push_back(shareKind(axes) ? "aspect: map (the longest axis is " + number(ratio) +
                                                              " times the shortest)"
                                                        : "aspect: map (the axes' units differ: " +
                                                              unitText(axes.units[0]) + ", " + unitText(axes.units[1]) +
                                                              ", " + unitText(axes.units[2]) + ")");
        }
    }
    switch (mode) {
        case Aspect::Mode::Physical: frame.scale = physicalScale(axes); break;
        case Aspect::Mode::Cubic: frame.scale = cubicScale(axes); break;
        case Aspect::Mode::Scale: frame.scale = settings.aspect.scale; break;
        case Aspect::Mode::Auto: frame.scale = mapScale(series, frame.rotation, axes, frame.explanation); break;
    }
    if (settings.aspect.mode != Aspect::Mode::Auto)
        frame.explanation.push_back("aspect: " + std::string(mode == Aspect::Mode::Physical ? "physical"
                                                             : mode == Aspect::Mode::Cubic ? "cubic"
                                                                                           : "scale"));
    if (settings.verticalExaggeration) {
        frame.verticalExaggeration = *settings.verticalExaggeration;
    } else if (map) {
        const double width = std::max(axes.extent.x * frame.scale.x, axes.extent.z * frame.scale.z);
        frame.verticalExaggeration = roundToTwoDigits(kMapHeightFraction * width / (axes.extent.y * frame.scale.y));
    }
    frame.scale.y *= frame.verticalExaggeration;
    if (frame.verticalExaggeration != 1.0)
        frame.explanation.push_back("vertical exaggeration: " + number(frame.verticalExaggeration) +
                                    (settings.verticalExaggeration ? "" : " (the height a quarter of the width)"));
    return frame;
}

namespace {

// The display axis each grid axis lies along, or none when the grid is turned between them.
std::optional<std::array<int, 3>> gridAxesOnDisplayAxes(const glm::dmat3& gridToDisplay) {
    std::array<int, 3> along{};
    for (int grid = 0; grid < 3; ++grid) {
        int found = -1;
        for (int display = 0; display < 3; ++display) {
            const double value = gridToDisplay[grid][display];
            if (std::abs(std::abs(value) - 1.0) < 1e-9) found = display;
            else if (std::abs(value) > 1e-9) return std::nullopt;
        }
        if (found < 0) return std::nullopt;
        along[std::size_t(grid)] = found;
    }
    return along;
}

void scaleGrid(Grid& grid, const glm::dvec3& byGridAxis, const std::string& where) {
    if (auto* rectilinear = std::get_if<RectilinearGrid>(&grid)) {
        rectilinear->spacing *= byGridAxis;
        for (int axis = 0; axis < 3; ++axis)
            for (double& position : rectilinear->axisPositions[std::size_t(axis)]) position *= byGridAxis[axis];
    } else if (auto* structured = std::get_if<StructuredGrid>(&grid)) {
        std::vector<glm::vec3> nodes = *structured->nodes;
        for (glm::vec3& node : nodes) node *= glm::vec3(byGridAxis);
        *structured = makeStructuredGrid(structured->dims, std::move(nodes), structured->coordinatesFile);
    } else {
        auto& beam = std::get<BeamGrid>(grid);
        if (byGridAxis.x != byGridAxis.y || byGridAxis.y != byGridAxis.z)
            throwInputError("", "aspect", where + " is a beam grid, which a scale that differs between axes would "
                                                  "distort; use \"aspect\": \"physical\"");
        beam.minRange *= byGridAxis.x;
        beam.maxRange *= byGridAxis.x;
    }
}

}  // namespace

Series applyDisplayFrame(Series series, const DisplayFrame& frame) {
    if (frame.isIdentity()) return series;
    const bool uniform = frame.scale.x == frame.scale.y && frame.scale.y == frame.scale.z;
    const glm::dquat turn = glm::quat_cast(frame.rotation);
    // Structured time-steps often share one grid: scale it once.
    struct ScaledGrid {
        const void* nodes;
        glm::dvec3 byGridAxis;
        StructuredGrid grid;
    };
    std::vector<ScaledGrid> scaledGrids;
    for (std::size_t index = 0; index < series.steps.size(); ++index) {
        TimeStep& step = series.steps[index];
        const std::string where = "time-step " + std::to_string(index) + " of " + series.manifestPath.string();
        const glm::dmat3 gridToDisplay = frame.rotation * glm::mat3_cast(step.placement.rotation);
        glm::dvec3 byGridAxis(frame.scale.x);
        if (!uniform) {
            const auto along = gridAxesOnDisplayAxes(gridToDisplay);
            if (!along)
                throwInputError("", "aspect", where + " is turned against the display axes, so a scale that differs "
                                                       "between axes would shear it; use \"aspect\": \"physical\"");
            for (int axis = 0; axis < 3; ++axis) byGridAxis[axis] = frame.scale[(*along)[std::size_t(axis)]];
        }
        step.placement.origin = frame.toDisplay(step.placement.origin);
        step.placement.rotation = glm::normalize(turn * step.placement.rotation);
        if (const StructuredGrid* structured = step.structured()) {
            const auto shared = std::find_if(scaledGrids.begin(), scaledGrids.end(),
                                             [&](const ScaledGrid& entry) {
                                                 return entry.nodes == structured->nodes.get() &&
                                                        entry.byGridAxis == byGridAxis;
                                             });
            if (shared != scaledGrids.end()) {
                step.grid = shared->grid;
                continue;
            }
            const void* key = structured->nodes.get();
            scaleGrid(step.grid, byGridAxis, where);
            scaledGrids.push_back({key, byGridAxis, std::get<StructuredGrid>(step.grid)});
            continue;
        }
        scaleGrid(step.grid, byGridAxis, where);
    }
    const std::array<SpatialAxis, 3> dataAxes = series.axes;
    const std::array<SignedAxis, 3> rows = rowsOf(frame.rotation);
    for (int display = 0; display < 3; ++display) {
        SpatialAxis axis = dataAxes[std::size_t(rows[std::size_t(display)].axis)];
        if (rows[std::size_t(display)].negated) axis.direction = opposite(axis.direction);
        series.axes[std::size_t(display)] = axis;
    }
    return series;
}

namespace {

// The series' axes as read, in data order: the shown series holds them in display order.
std::array<bool, 3> negatedDataAxes(const Series& shown, const DisplayFrame& frame) {
    const std::array<SignedAxis, 3> rows = rowsOf(frame.rotation);
    std::array<bool, 3> negated{};
    for (std::size_t display = 0; display < 3; ++display)
        negated[std::size_t(rows[display].axis)] = shown.axes[display].negated;
    return negated;
}

glm::dvec3 flipNegated(glm::dvec3 place, const std::array<bool, 3>& negated) {
    for (int axis = 0; axis < 3; ++axis)
        if (negated[std::size_t(axis)]) place[axis] = -place[axis];
    return place;
}

}  // namespace

glm::dvec3 fileCoordinatesOfShown(const Series& shown, const DisplayFrame& frame, const glm::dvec3& display) {
    return flipNegated(frame.toWorld(display), negatedDataAxes(shown, frame));
}

glm::dvec3 shownCoordinatesOfFile(const Series& shown, const DisplayFrame& frame, const glm::dvec3& file) {
    return frame.toDisplay(flipNegated(file, negatedDataAxes(shown, frame)));
}

}  // namespace tstyles
