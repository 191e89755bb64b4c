// The data model of a time-varying volume: a series of time-steps, each on its own grid and world
// placement. Knows nothing of OpenGL; the renderer uploads what it finds here.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "tstyles/data/structured_grid.h"
#include "tstyles/data/time_axis.h"

namespace tstyles {

// A voxel without data (a fill value, land under a weather model's atmosphere): neither a density
// nor zero. Readers store it as a quiet NaN in TimeStep::density; the renderer treats it as
// transparent and leaves it out of every temporal compositor. NaN in a source file's float data is
// missing in every format, declared or not (as napari, Fiji and ParaView read it); Inf is bad input.
inline float missingDensity() { return std::nanf(""); }
inline bool isMissing(float density) { return std::isnan(density); }

// How the values of a time-step are stored in its raw file (little-endian), or in the file a
// reader took them from.
enum class ValueType { UInt8, UInt16, Float32, Int8, Int16, Int32, Float64 };

std::string toString(ValueType type);
std::optional<ValueType> valueTypeFromString(const std::string& name);
std::size_t bytesPerValue(ValueType type);

// A regular lattice: dims samples along x, y, z, `spacing` world units apart. Samples sit on the
// nodes, so the grid spans (dims - 1) * spacing along each axis, starting at the placement origin.
struct RectilinearGrid {
    glm::ivec3 dims{0};
    glm::dvec3 spacing{1.0};
    // Uneven axes (ocean depth or pressure levels): where non-empty, the grid-local positions of
    // the nodes along that axis, dims[axis] strictly increasing values starting at 0; `spacing` is
    // then unused for that axis. Empty means evenly spaced nodes.
    std::array<std::vector<double>, 3> axisPositions;

    bool isUneven(int axis) const { return !axisPositions[std::size_t(axis)].empty(); }
    glm::dvec3 extent() const {
        glm::dvec3 result = glm::dvec3(dims - 1) * spacing;
        for (int axis = 0; axis < 3; ++axis)
            if (isUneven(axis)) result[axis] = axisPositions[std::size_t(axis)].back();
        return result;
    }
    std::size_t voxelCount() const {
        return std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
    }
};

// A sonar ping's beam (spherical-sector) grid: dims.x beams across (azimuth) times dims.y beams
// along (elevation), each sampled at dims.z ranges from minRange to maxRange. The transducer sits
// at the grid-local origin looking along +z; a beam's direction is normalize(tan(azimuth),
// tan(elevation), 1): azimuth is the angle in the x-z plane, elevation the angle in the y-z plane,
// so the fan's sides are planes through the transducer. Sample (i, j, k) lies on beam (i, j) at
// range minRange + k * rangeSpacing(). Geometry helpers: tstyles/data/beam_geometry.h.
struct BeamGrid {
    glm::ivec3 dims{0};
    // One angle per beam in degrees, strictly increasing, each in (-90, 90): dims.x azimuths and
    // dims.y elevations (evenly spread ones when the manifest gives only the extent).
    std::vector<double> azimuthDeg;
    std::vector<double> elevationDeg;
    double minRange = 0.0;
    double maxRange = 1.0;

    double rangeSpacing() const { return (maxRange - minRange) / double(dims.z - 1); }
    std::size_t voxelCount() const {
        return std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
    }
    bool operator==(const BeamGrid& other) const = default;
};

using Grid = std::variant<RectilinearGrid, StructuredGrid, BeamGrid>;

// Samples along each axis and in all, whatever the grid kind.
glm::ivec3 gridDims(const Grid& grid);
std::size_t gridVoxelCount(const Grid& grid);
// The grid kind as manifests and `tstyles info` name it ("rectilinear", "structured", "beam").
std::string gridTypeName(const Grid& grid);

// Where a time-step's grid sits in the world: grid-local position p maps to origin + rotation * p.
struct Placement {
    glm::dvec3 origin{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};

    glm::dmat4 gridToWorld() const;
    bool operator==(const Placement& other) const {
        return origin == other.origin && rotation == other.rotation;
    }
};

// A rotation as manifests spell it: a unit axis and an angle in degrees, right-handed.
struct AxisAngle {
    glm::dvec3 axis{0.0, 0.0, 1.0};
    double angleDeg = 0.0;
};

// The identity comes back as axis +z, angle 0; angles lie in [0, 180].
AxisAngle toAxisAngle(const glm::dquat& rotation);
// The axis need not be unit length but must not be zero.
glm::dquat fromAxisAngle(const AxisAngle& rotation);

// One moment of the series.
struct TimeStep {
    double time = 0.0;
    Grid grid;
    Placement placement;
    ValueType sourceType = ValueType::Float32;
    // The raw values' own minimum and maximum, as read from the file.
    std::array<double, 2> rawRange{0.0, 0.0};
    // Values mapped to [0,1] by the series' value range (clamped), x fastest, then y, then z.
    std::vector<float> density;
    // Optional segmentation mask, same dims: 0 outside the region of interest, non-zero inside.
    std::optional<std::vector<std::uint8_t>> mask;
    // Where the values and the mask came from (for messages and `tstyles info`).
    std::filesystem::path valuesFile;
    std::filesystem::path maskFile;

    const RectilinearGrid& rectilinear() const { return std::get<RectilinearGrid>(grid); }
    // The structured grid, or null for other grid kinds.
    const StructuredGrid* structured() const { return std::get_if<StructuredGrid>(&grid); }
    glm::ivec3 dims() const { return gridDims(grid); }
    bool isBeam() const { return std::holds_alternative<BeamGrid>(grid); }
    const BeamGrid& beam() const { return std::get<BeamGrid>(grid); }
};

// World-space axis-aligned box.
struct Bounds {
    glm::dvec3 lower{0.0};
    glm::dvec3 upper{0.0};
    glm::dvec3 center() const { return 0.5 * (lower + upper); }
    glm::dvec3 size() const { return upper - lower; }
};

// What the positive direction of a world axis points toward, where the file says so (CF
// attributes, NIfTI and NRRD orientation). Opposites are separate values, so a reader states what
// +axis means without flipping data; the automatic scene turns these into a display frame
// (docs/automatic-scene.md).
enum class AxisDirection {
    Unknown,
    East, West, North, South, Up, Down,                      // geographic
    Right, Left, Anterior, Posterior, Superior, Inferior,   // anatomical (the patient's)
};

std::string toString(AxisDirection direction);  // "east", "anterior", "unknown", ...
std::optional<AxisDirection> axisDirectionFromString(const std::string& name);
// East for west, up for down, ...; unknown stays unknown.
AxisDirection opposite(AxisDirection direction);

// One world axis of a series as the file describes it.
struct SpatialAxis {
    std::string name;  // the file's name for it ("lon", "depth"); empty: none given
    std::string unit;  // as the file spells it ("degrees_east", "m", "hPa", "mm"); empty: unknown
    AxisDirection direction = AxisDirection::Unknown;
    // The world coordinate is the file's value negated: a CF axis that counts downward (depth,
    // pressure) drawn pointing up. `info` lists, and `probe --at` takes, the file's own values
    // (500 hPa, not -500): fileCoordinatesOf and worldCoordinatesOf.
    bool negated = false;
    bool operator==(const SpatialAxis&) const = default;
};

// Bits per density sample on the GPU: R8, R16 or R32F textures.
enum class DensityPrecision { Bits8, Bits16, Bits32 };

struct Series {
    std::string name;
    std::filesystem::path manifestPath;
    // The raw values mapped to density 0 and 1.
    std::array<double, 2> valueRange{0.0, 1.0};
    // The values' unit as the file spells it ("K", "m s-1"); empty: unknown. For legends.
    std::string valueUnit;
    std::vector<TimeStep> steps;
    // How the GPU stores the densities (ReadOptions::precision, --precision): R8, R16 or R32F
    // (RG pairs with missing values); the reader's memory check assumes the same.
    DensityPrecision precision = DensityPrecision::Bits16;
    // The file format it was read from ("tstyles manifest", "NetCDF-4", "NRRD", ...).
    std::string sourceFormat = "tstyles manifest";
    // How the reader read it, a line each, where the file left a choice ("ImageJ hyperstack: 5 frames
    // x 12 slices x 2 channels, channel 0 taken", "series 2 of 3 (the largest)"). `info` prints them.
    std::vector<std::string> readingNotes;
    // What world x, y and z mean, in that order, as far as the source says.
    std::array<SpatialAxis, 3> axes;
    // What TimeStep::time means: its unit and, where the file gives one, the date it counts from.
    TimeAxis time;

    std::size_t size() const { return steps.size(); }
    bool hasMasks() const;
    // World bounds of the time-step's grid after placement (a box's eight corners, a beam fan's
    // enclosing mesh).
    Bounds worldBounds(std::size_t step) const;
    // World bounds of the whole series.
    Bounds worldBounds() const;
    // The smallest sample spacing of any time-step: the default ray step is half of it.
    double finestSpacing() const;
};

// A world place in the file's own coordinates (the negated axes' values as the file has them), and
// a place in the file's coordinates in the world: each flips the sign of the negated axes.
glm::dvec3 fileCoordinatesOf(const Series& series, const glm::dvec3& world);
glm::dvec3 worldCoordinatesOf(const Series& series, const glm::dvec3& file);
// The series' world bounds in the file's coordinates, lower to upper on every axis.
Bounds fileBounds(const Series& series);
// Whether an axis of the series is negated.
bool hasNegatedAxes(const Series& series);

// For series made from another (coarser, an outline for annotations): everything of `series` but
// its time-steps; and everything of a time-step but its values and mask.
Series withoutTimeSteps(const Series& series);
TimeStep withoutValues(const TimeStep& step);

}  // namespace tstyles
