// The text of `tstyles info`: a series' time-steps, how they overlap in the world, and what they
// cost in memory.
#include "tstyles/data/series_summary.h"

#include "tstyles/data/beam_geometry.h"
#include "tstyles/data/inverse_map.h"
#include "tstyles/data/read_options.h"

#include <algorithm>
#include <cmath>
#include <variant>
#include <iomanip>
#include <sstream>
#include <vector>

namespace tstyles {
namespace {

constexpr double kBytesPerMiB = 1024.0 * 1024.0;
// Density goes to the GPU at the series' precision (8, 16 or 32 bits), paired with a validity
// channel when values are missing; masks as 8-bit.
constexpr std::size_t kGpuBytesPerMaskVoxel = 1;

// Six significant digits, as %g; adding 0.0 turns -0 into 0 so rotated origins do not print "-0".
std::string number(double value) {
    std::ostringstream text;
    text << std::setprecision(6) << (value + 0.0);
    return text.str();
}

std::string vec3Text(const glm::dvec3& v) {
    return std::string("(") + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
}

std::string mibText(std::size_t bytes) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(2) << double(bytes) / kBytesPerMiB << " MiB";
    return text.str();
}

double volume(const Bounds& bounds) {
    const glm::dvec3 size = glm::max(bounds.size(), glm::dvec3(0.0));
    return size.x * size.y * size.z;
}

std::string rotationText(const glm::dquat& rotation) {
    const AxisAngle axisAngle = toAxisAngle(rotation);
    if (axisAngle.angleDeg == 0.0) return "none";
    return number(axisAngle.angleDeg) + " deg about " + vec3Text(axisAngle.axis);
}

using Row = std::vector<std::string>;

// Left-aligned columns, each as wide as its widest cell, two spaces apart.
void printTable(std::ostream& out, const std::vector<Row>& rows) {
    std::vector<std::size_t> widths;
    for (const Row& row : rows) {
        widths.resize(std::max(widths.size(), row.size()), 0);
        for (std::size_t column = 0; column < row.size(); ++column) {
            widths[column] = std::max(widths[column], row[column].size());
        }
    }
    for (const Row& row : rows) {
        std::string line = "  ";
        for (std::size_t column = 0; column < row.size(); ++column) {
            line += row[column];
            if (column + 1 < row.size()) line += std::string(widths[column] - row[column].size() + 2, ' ');
        }
        out << line << "\n";
    }
}

// Per axis the spacing, or "uneven" where the axis lists its node positions.
std::string spacingText(const RectilinearGrid& grid) {
    std::string text = "(";
    for (int axis = 0; axis < 3; ++axis)
        text += (axis > 0 ? ", " : "") + (grid.isUneven(axis) ? std::string("uneven") : number(grid.spacing[axis]));
    return text + ")";
}

std::size_t missingVoxels(const TimeStep& step) {
    return std::size_t(std::count_if(step.density.begin(), step.density.end(), [](float d) { return isMissing(d); }));
}

std::string dimsText(const glm::ivec3& dims) {
    return std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
}

std::string angleSpanText(const std::vector<double>& anglesDeg) {
    return number(anglesDeg.front()) + ".." + number(anglesDeg.back()) +
           (areEvenBeamAngles(anglesDeg) ? "" : " uneven");
}

// The grid's kind and size, and its spacing: a box's distances, or a fan's angles and ranges.
std::array<std::string, 2> gridText(const TimeStep& step) {
    if (step.isBeam()) {
        const BeamGrid& grid = step.beam();
        return {"beam " + dimsText(grid.dims),
                "az " + angleSpanText(grid.azimuthDeg) + " el " + angleSpanText(grid.elevationDeg) +
                    " deg, range " + number(grid.minRange) + ".." + number(grid.maxRange)};
    }
    if (const StructuredGrid* structured = step.structured())
        return {"structured " + dimsText(structured->dims), "curvilinear, edges from " + number(structured->finestEdge)};
    const RectilinearGrid& grid = step.rectilinear();
    return {"rectilinear " + dimsText(grid.dims), spacingText(grid)};
}

Row stepRow(const Series& series, std::size_t index, const std::string& time) {
    const TimeStep& step = series.steps[index];
    const auto [grid, spacing] = gridText(step);
    return {std::to_string(index),
            time,
            grid,
            spacing,
            vec3Text(step.placement.origin),
            rotationText(step.placement.rotation),
            (std::isnan(step.rawRange[0]) ? std::string("no data")
                                          : number(step.rawRange[0]) + " .. " + number(step.rawRange[1])) +
                " " + toString(step.sourceType),
            step.mask ? "yes" : "no"};
}

void printOverlaps(std::ostream& out, const Series& series) {
    if (series.size() < 2) {
        out << "Overlap: a single time-step\n";
        return;
    }
    out << "Overlap of adjacent time-steps (share of the smaller world box inside both):\n";
    std::vector<Row> rows;
    for (std::size_t index = 0; index + 1 < series.size(); ++index) {
        std::ostringstream percent;
        percent << std::fixed << std::setprecision(1) << 100.0 * overlapFraction(series, index, index + 1)
                << " %";
        rows.push_back({std::to_string(index) + " - " + std::to_string(index + 1), percent.str()});
    }
    printTable(out, rows);
}

std::string structuredGridsText(const Series& series) {
    const std::vector<const StructuredGrid*> grids = distinctStructuredGrids(series);
    if (grids.empty()) return {};
    std::ostringstream out;
    out << "Structured grids: " << grids.size() << " (node coordinates per node; samples are located through an "
        << "inverse map of RGBA32F texels over each grid's bounds)\n";
    for (const StructuredGrid* grid : grids) {
        const glm::ivec3 map = inverseMapDims(*grid);
        out << "  " << (grid->coordinatesFile.empty() ? std::string("(in memory)") : grid->coordinatesFile.string())
            << ": " << grid->dims.x << "x" << grid->dims.y << "x" << grid->dims.z << " nodes, local bounds "
            << vec3Text(grid->localLower) << " to " << vec3Text(grid->localUpper) << ", inverse map " << map.x << "x"
            << map.y << "x" << map.z << " (" << mibText(std::size_t(map.x) * map.y * map.z * 16) << ")\n";
    }
    return out.str();
}

bool sameGrid(const TimeStep& a, const TimeStep& b) {
    if (a.grid.index() != b.grid.index()) return false;
    if (a.isBeam()) return a.beam() == b.beam();
    if (const StructuredGrid* structured = a.structured()) return structured->nodes == b.structured()->nodes;
    return a.dims() == b.dims() && a.rectilinear().spacing == b.rectilinear().spacing &&
           a.rectilinear().axisPositions == b.rectilinear().axisPositions;
}

}  // namespace

std::vector<const StructuredGrid*> distinctStructuredGrids(const Series& series) {
    std::vector<const StructuredGrid*> grids;
    for (const TimeStep& step : series.steps) {
        const StructuredGrid* grid = step.structured();
        if (!grid) continue;
        const bool known = std::any_of(grids.begin(), grids.end(),
                                       [grid](const StructuredGrid* other) { return other->nodes == grid->nodes; });
        if (!known) grids.push_back(grid);
    }
    return grids;
}

std::size_t inverseMapBytes(const Series& series) {
    std::size_t bytes = 0;
    for (const StructuredGrid* grid : distinctStructuredGrids(series)) {
        const glm::ivec3 map = inverseMapDims(*grid);
        bytes += std::size_t(map.x) * std::size_t(map.y) * std::size_t(map.z) * sizeof(glm::vec4);
    }
    return bytes;
}

bool isFullyAligned(const Series& series) {
    if (series.steps.empty()) return true;
    const TimeStep& first = series.steps.front();
    return std::all_of(series.steps.begin(), series.steps.end(), [&first](const TimeStep& step) {
        return sameGrid(step, first) && step.placement == first.placement;
    });
}

double overlapFraction(const Series& series, std::size_t a, std::size_t b) {
    const Bounds first = series.worldBounds(a);
    const Bounds second = series.worldBounds(b);
    const Bounds both{glm::max(first.lower, second.lower), glm::min(first.upper, second.upper)};
    const double smaller = std::min(volume(first), volume(second));
    // Grids span at least two samples per axis, so a zero volume only comes from a hand-made Series.
    if (smaller <= 0.0) return 0.0;
    return std::clamp(volume(both) / smaller, 0.0, 1.0);
}

std::size_t diskBytes(const Series& series) {
    std::size_t bytes = 0;
    for (const TimeStep& step : series.steps) {
        const std::size_t voxels = gridVoxelCount(step.grid);
        bytes += voxels * bytesPerValue(step.sourceType) + (step.mask ? voxels : 0);
    }
    for (const StructuredGrid* grid : distinctStructuredGrids(series)) bytes += grid->voxelCount() * 12;
    return bytes;
}

bool anyMissing(const Series& series) {
    return std::any_of(series.steps.begin(), series.steps.end(),
                       [](const TimeStep& step) { return missingVoxels(step) > 0; });
}

std::size_t gpuBytesPerDensityVoxel(const Series& series) {
    return bytesPerDensity(series.precision) * (anyMissing(series) ? 2 : 1);
}

std::size_t gpuBytes(const Series& series) {
    std::size_t bytes = 0;
    for (const TimeStep& step : series.steps) {
        const std::size_t voxels = gridVoxelCount(step.grid);
        bytes += voxels * gpuBytesPerDensityVoxel(series) + (step.mask ? voxels * kGpuBytesPerMaskVoxel : 0);
    }
    return bytes + inverseMapBytes(series);
}

std::string describeSeries(const Series& series) {
    std::ostringstream out;
    out << "Series: " << series.name << "\n";
    out << (series.sourceFormat == "tstyles manifest" ? "Manifest: " : "File: ") << series.manifestPath.string()
        << "\n";
    out << "Format: " << series.sourceFormat << "\n";
    for (const std::string& note : series.readingNotes) out << "Read: " << note << "\n";
    out << "Time-steps: " << series.size() << "\n";
    out << "Value range: [" << number(series.valueRange[0]) << ", " << number(series.valueRange[1])
        << "] maps to density [0, 1]\n";
    std::size_t missing = 0;
    std::size_t voxels = 0;
    for (const TimeStep& step : series.steps) {
        missing += missingVoxels(step);
        voxels += step.density.size();
    }
    if (missing > 0) {
        std::ostringstream share;
        share << std::fixed << std::setprecision(1) << 100.0 * double(missing) / double(voxels);
        out << "Missing values: " << missing << " voxels without data (" << share.str() << " %)\n";
    }
    out << "Alignment: "
        << (isFullyAligned(series) ? "fully aligned: one common grid"
                                   : "partial overlap: time-steps differ in grid or placement")
        << "\n";
    if (!series.steps.empty()) {
        const Bounds bounds = series.worldBounds();
        out << "World bounds: " << vec3Text(bounds.lower) << " to " << vec3Text(bounds.upper) << "\n";
        if (hasNegatedAxes(series)) {
            const Bounds file = fileBounds(series);
            out << "File coordinates: " << vec3Text(file.lower) << " to " << vec3Text(file.upper)
                << " (a negated axis counts down in the file: its values, as probe --at takes them)\n";
        }
    }

    if (series.axes != std::array<SpatialAxis, 3>{}) {
        out << "Axes:";
        for (int axis = 0; axis < 3; ++axis) {
            const SpatialAxis& described = series.axes[std::size_t(axis)];
            out << (axis ? "," : "") << " " << char('x' + axis) << " = " << (described.name.empty() ? "-" : described.name)
                << " (" << (described.unit.empty() ? "no unit" : described.unit) << ", " << toString(described.direction)
                << (described.negated ? ", negated" : "") << ")";
        }
        out << "\n";
    }
    if (series.time.unit != TimeUnit::None)
        out << "Time: " << toCfUnits(series.time)
            << (series.time.reference ? " (" + toString(series.time.calendar) + " calendar)" : "")
            << (series.time.climatology ? ", a climatology" : "") << "\n";
    out << "\n";
    std::vector<double> times;
    for (const TimeStep& step : series.steps) times.push_back(step.time);
    const std::vector<std::string> labels = formatTimes(times, series.time);
    std::vector<Row> rows{{"#", "time", "grid", "spacing", "origin", "rotation", "raw min .. max", "mask"}};
    for (std::size_t index = 0; index < series.size(); ++index) rows.push_back(stepRow(series, index, labels[index]));
    printTable(out, rows);
    out << "\n";

    printOverlaps(out, series);
    out << "\n";
    out << structuredGridsText(series);
    out << "Memory: " << mibText(diskBytes(series)) << " on disk, " << mibText(gpuBytes(series))
        << " on the GPU (" << precisionBits(series.precision) << "-bit density"
        << (anyMissing(series) ? " + validity" : "") << (series.hasMasks() ? " + 8-bit mask" : "") << " per voxel"
        << (inverseMapBytes(series) > 0 ? ", inverse maps" : "") << ")\n";
    return out.str();
}

}  // namespace tstyles
