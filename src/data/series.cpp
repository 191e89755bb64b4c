// Geometry of a series: value types, grid placement in the world, and the bounds and spacing the
// renderer sizes its rays by.
#include "tstyles/data/series.h"

#include "tstyles/data/grid_axes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "tstyles/data/beam_geometry.h"

namespace tstyles {

std::string toString(ValueType type) {
    switch (type) {
        case ValueType::UInt8:
            return "uint8";
        case ValueType::UInt16:
            return "uint16";
        case ValueType::Float32:
            return "float32";
        case ValueType::Int8:
            return "int8";
        case ValueType::Int16:
            return "int16";
        case ValueType::Int32:
            return "int32";
        case ValueType::Float64:
            return "float64";
    }
    throw std::logic_error("toString: ValueType out of range");
}

std::string toString(AxisDirection direction) {
    static constexpr const char* kNames[] = {"unknown", "east",     "west",      "north",    "south",
                                             "up",      "down",     "right",     "left",     "anterior",
                                             "posterior", "superior", "inferior"};
    return kNames[static_cast<int>(direction)];
}

std::optional<AxisDirection> axisDirectionFromString(const std::string& name) {
    for (int value = 0; value <= static_cast<int>(AxisDirection::Inferior); ++value)
        if (toString(static_cast<AxisDirection>(value)) == name) return static_cast<AxisDirection>(value);
    return std::nullopt;
}

AxisDirection opposite(AxisDirection direction) {
    switch (direction) {
        case AxisDirection::East: return AxisDirection::West;
        case AxisDirection::West: return AxisDirection::East;
        case AxisDirection::North: return AxisDirection::South;
        case AxisDirection::South: return AxisDirection::North;
        case AxisDirection::Up: return AxisDirection::Down;
        case AxisDirection::Down: return AxisDirection::Up;
        case AxisDirection::Right: return AxisDirection::Left;
        case AxisDirection::Left: return AxisDirection::Right;
        case AxisDirection::Anterior: return AxisDirection::Posterior;
        case AxisDirection::Posterior: return AxisDirection::Anterior;
        case AxisDirection::Superior: return AxisDirection::Inferior;
        case AxisDirection::Inferior: return AxisDirection::Superior;
        case AxisDirection::Unknown: return AxisDirection::Unknown;
    }
    return AxisDirection::Unknown;
}

std::optional<ValueType> valueTypeFromString(const std::string& name) {
    for (ValueType type : {ValueType::UInt8, ValueType::UInt16, ValueType::Float32, ValueType::Int8,
                           ValueType::Int16, ValueType::Int32, ValueType::Float64}) {
        if (toString(type) == name) return type;
    }
    return std::nullopt;
}

std::size_t bytesPerValue(ValueType type) {
    switch (type) {
        case ValueType::UInt8:
        case ValueType::Int8:
            return 1;
        case ValueType::UInt16:
        case ValueType::Int16:
            return 2;
        case ValueType::Float32:
        case ValueType::Int32:
            return 4;
        case ValueType::Float64:
            return 8;
    }
    throw std::logic_error("bytesPerValue: ValueType out of range");
}

glm::dmat4 Placement::gridToWorld() const {
    return glm::translate(glm::dmat4(1.0), origin) * glm::mat4_cast(rotation);
}

AxisAngle toAxisAngle(const glm::dquat& rotation) {
    glm::dquat unit = glm::normalize(rotation);
    // q and -q are the same rotation; choosing w >= 0 keeps the angle in [0, 180].
    if (unit.w < 0.0) unit = -unit;
    const glm::dvec3 imaginary(unit.x, unit.y, unit.z);
    const double sinHalfAngle = glm::length(imaginary);
    // Below this the axis is numerical noise; the rotation is the identity to double precision.
    if (sinHalfAngle < 1e-15) return AxisAngle{};
    return AxisAngle{imaginary / sinHalfAngle, glm::degrees(2.0 * std::atan2(sinHalfAngle, unit.w))};
}

glm::dquat fromAxisAngle(const AxisAngle& rotation) {
    return glm::angleAxis(glm::radians(rotation.angleDeg), glm::normalize(rotation.axis));
}

glm::ivec3 gridDims(const Grid& grid) {
    return std::visit([](const auto& kind) { return kind.dims; }, grid);
}

std::size_t gridVoxelCount(const Grid& grid) {
    return std::visit([](const auto& kind) { return kind.voxelCount(); }, grid);
}

std::string gridTypeName(const Grid& grid) {
    if (std::holds_alternative<StructuredGrid>(grid)) return "structured";
    if (std::holds_alternative<BeamGrid>(grid)) return "beam";
    return "rectilinear";
}

bool Series::hasMasks() const {
    return std::any_of(steps.begin(), steps.end(),
                       [](const TimeStep& step) { return step.mask.has_value(); });
}

Bounds Series::worldBounds(std::size_t step) const {
    const TimeStep& timeStep = steps.at(step);
    const glm::dmat4 toWorld = timeStep.placement.gridToWorld();
    Bounds bounds{glm::dvec3(std::numeric_limits<double>::infinity()),
                  glm::dvec3(-std::numeric_limits<double>::infinity())};
    auto include = [&](const glm::dvec3& local) {
        const glm::dvec3 world(toWorld * glm::dvec4(local, 1.0));
        bounds.lower = glm::min(bounds.lower, world);
        bounds.upper = glm::max(bounds.upper, world);
    };
    if (timeStep.isBeam()) {
        // The fan's enclosing mesh: its far cap bulges past the corners, and lies just outside it.
        for (const Triangle& triangle : beamFanBoundary(timeStep.beam()))
            for (const glm::dvec3& corner : triangle) include(corner);
        return bounds;
    }
    // Grid-local bounds: the lattice's box, or the box of a structured grid's nodes.
    glm::dvec3 localLower(0.0);
    glm::dvec3 extent(0.0);
    if (const StructuredGrid* structured = timeStep.structured()) {
        localLower = structured->localLower;
        extent = structured->localUpper - structured->localLower;
    } else {
        extent = timeStep.rectilinear().extent();
    }
    // A rotated box's axis-aligned bounds are reached at its corners, so eight points suffice.
    for (int corner = 0; corner < 8; ++corner) {
        include(localLower + glm::dvec3((corner & 1) ? extent.x : 0.0, (corner & 2) ? extent.y : 0.0,
                                        (corner & 4) ? extent.z : 0.0));
    }
    return bounds;
}

Series withoutTimeSteps(const Series& series) {
    Series result;
    result.name = series.name;
    result.manifestPath = series.manifestPath;
    result.valueRange = series.valueRange;
    result.valueUnit = series.valueUnit;
    result.precision = series.precision;
    result.sourceFormat = series.sourceFormat;
    result.readingNotes = series.readingNotes;
    result.axes = series.axes;
    result.time = series.time;
    return result;
}

TimeStep withoutValues(const TimeStep& step) {
    TimeStep result;
    result.time = step.time;
    result.grid = step.grid;
    result.placement = step.placement;
    result.sourceType = step.sourceType;
    result.rawRange = step.rawRange;
    result.valuesFile = step.valuesFile;
    result.maskFile = step.maskFile;
    return result;
}

Bounds Series::worldBounds() const {
    if (steps.empty()) throw std::logic_error("Series::worldBounds: the series has no time-steps");
    Bounds all = worldBounds(0);
    for (std::size_t step = 1; step < steps.size(); ++step) {
        const Bounds bounds = worldBounds(step);
        all.lower = glm::min(all.lower, bounds.lower);
        all.upper = glm::max(all.upper, bounds.upper);
    }
    return all;
}

glm::dvec3 fileCoordinatesOf(const Series& series, const glm::dvec3& world) {
    glm::dvec3 file = world;
    for (int axis = 0; axis < 3; ++axis)
        if (series.axes[std::size_t(axis)].negated) file[axis] = -file[axis];
    return file;
}

glm::dvec3 worldCoordinatesOf(const Series& series, const glm::dvec3& file) { return fileCoordinatesOf(series, file); }

Bounds fileBounds(const Series& series) {
    const Bounds world = series.worldBounds();
    const glm::dvec3 a = fileCoordinatesOf(series, world.lower);
    const glm::dvec3 b = fileCoordinatesOf(series, world.upper);
    return {glm::min(a, b), glm::max(a, b)};
}

bool hasNegatedAxes(const Series& series) {
    return std::any_of(series.axes.begin(), series.axes.end(), [](const SpatialAxis& axis) { return axis.negated; });
}

double Series::finestSpacing() const {
    if (steps.empty()) throw std::logic_error("Series::finestSpacing: the series has no time-steps");
    double finest = std::numeric_limits<double>::infinity();
    for (const TimeStep& step : steps) {
        if (const StructuredGrid* structured = step.structured()) {
            finest = std::min(finest, structured->finestEdge);
            continue;
        }
        if (step.isBeam()) {
            finest = std::min(finest, beamFinestSpacing(step.beam()));
            continue;
        }
        finest = std::min(finest, tstyles::finestSpacing(step.rectilinear()));
    }
    return finest;
}

}  // namespace tstyles
