// Writing a series to disk: one raw file per time-step (and mask), then the manifest last, so a
// folder with a series.json always has every file that manifest names.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <cstddef>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/beam_geometry.h"
#include "tstyles/data/manifest.h"

namespace tstyles {
namespace {

using OrderedJson = nlohmann::ordered_json;

glm::ivec3 dimsOf(const RawTimeStep& step) {
    if (step.structured) return step.structured->dims;
    if (step.beamGrid) return step.beamGrid->dims;
    return step.grid.dims;
}

std::size_t voxelCountOf(const RawTimeStep& step) {
    const glm::ivec3 dims = dimsOf(step);
    return std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
}

void checkWritableBeamGrid(const BeamGrid& grid, const std::string& where) {
    const auto increasing = [](const std::vector<double>& angles, int count) {
        if (angles.size() != std::size_t(count)) return false;
        for (std::size_t index = 0; index < angles.size(); ++index) {
            if (!(angles[index] > -80.0 && angles[index] < 80.0)) return false;
            if (index > 0 && !(angles[index] > angles[index - 1])) return false;
        }
        return true;
    };
    if (!increasing(grid.azimuthDeg, grid.dims.x) || !increasing(grid.elevationDeg, grid.dims.y))
        throw std::invalid_argument("writeSeries: " + where + "beam angles must be one per beam, increasing, in (-80, 80)");
    if (!(grid.minRange >= 0.0 && grid.minRange < grid.maxRange && std::isfinite(grid.maxRange)))
        throw std::invalid_argument("writeSeries: " + where + "beam range must satisfy 0 <= min < max");
}

// A RawSeries that loadSeries would reject is a bug in the caller (a generator), not bad user input.
void checkWritable(const RawSeries& series) {
    const auto fail = [](const std::string& problem) {
        throw std::invalid_argument("writeSeries: " + problem);
    };
    if (series.steps.empty()) fail("the series has no time-steps");
    if (!(std::isfinite(series.valueRange[0]) && std::isfinite(series.valueRange[1]) &&
          series.valueRange[0] < series.valueRange[1])) {
        fail("value range must be finite with low < high");
    }
    for (std::size_t index = 0; index < series.steps.size(); ++index) {
        const RawTimeStep& step = series.steps[index];
        const std::string where = "time-step " + std::to_string(index) + ": ";
        if (glm::any(glm::lessThan(dimsOf(step), glm::ivec3(2)))) fail(where + "dims must be at least 2");
        if (step.beamGrid) checkWritableBeamGrid(*step.beamGrid, where);
        const std::size_t voxels = voxelCountOf(step);
        if (step.bytes.size() != voxels * bytesPerValue(step.type)) {
            fail(where + "has " + std::to_string(step.bytes.size()) + " value bytes, expected " +
                 std::to_string(voxels * bytesPerValue(step.type)));
        }
        if (step.mask && step.mask->size() != voxels) {
            fail(where + "mask has " + std::to_string(step.mask->size()) + " bytes, expected " +
                 std::to_string(voxels));
        }
        if (index > 0 && !(step.time > series.steps[index - 1].time)) fail(where + "times must increase");
        for (int axis = 0; axis < 3; ++axis) {
            const std::vector<double>& nodes = step.grid.axisPositions[std::size_t(axis)];
            if (nodes.empty()) continue;
            if (nodes.size() != std::size_t(step.grid.dims[axis]) || nodes.front() != 0.0 ||
                !std::is_sorted(nodes.begin(), nodes.end(), std::less_equal<>()) ||
                std::adjacent_find(nodes.begin(), nodes.end()) != nodes.end()) {
                fail(where + "axis positions must be dims[axis] strictly increasing values from 0");
            }
        }
    }
}

// t00, t01, ... wide enough that the names sort in time order.
std::string stepFileStem(std::size_t index, std::size_t stepCount) {
    const std::size_t width = std::max<std::size_t>(2, std::to_string(stepCount - 1).size());
    std::string digits = std::to_string(index);
    return std::string("t") + std::string(width - digits.size(), '0') + digits;
}

OrderedJson vec3Json(const glm::dvec3& v) {
    return OrderedJson::array({v.x, v.y, v.z});
}

// Evenly spread beams are written as their extent, others angle by angle.
OrderedJson beamGridJson(const BeamGrid& grid) {
    OrderedJson json;
    json["type"] = "beam";
    json["dims"] = OrderedJson::array({grid.dims.x, grid.dims.y, grid.dims.z});
    const auto angles = [&](const char* name, const std::vector<double>& values) {
        if (areEvenBeamAngles(values))
            json[std::string(name) + "_deg"] = OrderedJson::array({values.front(), values.back()});
        else
            json[std::string(name) + "_angles_deg"] = values;
    };
    angles("azimuth", grid.azimuthDeg);
    angles("elevation", grid.elevationDeg);
    json["range"] = OrderedJson::array({grid.minRange, grid.maxRange});
    return json;
}

OrderedJson stepJson(const RawTimeStep& step, const std::string& stem, const std::string& coordinatesFile) {
    const AxisAngle rotation = toAxisAngle(step.placement.rotation);
    OrderedJson json;
    json["time"] = step.time;
    const glm::ivec3 dims = dimsOf(step);
    if (step.beamGrid) {
        json["grid"] = beamGridJson(*step.beamGrid);
    } else if (step.structured) {
        json["grid"] = {{"type", "structured"},
                        {"dims", OrderedJson::array({dims.x, dims.y, dims.z})},
                        {"coordinates", {{"file", coordinatesFile}}}};
    } else {
        json["grid"] = {{"type", "rectilinear"},
                        {"dims", OrderedJson::array({dims.x, dims.y, dims.z})},
                        {"spacing", vec3Json(step.grid.spacing)}};
        // An uneven axis: its nodes under "positions" and null for its spacing.
        for (int axis = 0; axis < 3; ++axis) {
            if (!step.grid.isUneven(axis)) continue;
            const std::string name(1, "xyz"[axis]);
            json["grid"]["spacing"][std::size_t(axis)] = nullptr;
            json["grid"]["positions"][name] = step.grid.axisPositions[std::size_t(axis)];
        }
    }
    json["placement"] = {{"origin", vec3Json(step.placement.origin)},
                         {"rotation", {{"axis", vec3Json(rotation.axis)}, {"angle_deg", rotation.angleDeg}}}};
    json["values"] = {{"file", stem + ".raw"}, {"type", toString(step.type)}};
    if (step.mask) json["mask"] = {{"file", stem + "_mask.raw"}};
    return json;
}

// Like dump(2), except that arrays of numbers or strings stay on one line: nlohmann would give each
// component of every vector its own line, which buries the structure a reader looks for.
void appendReadable(std::string& out, const OrderedJson& value, std::size_t indent) {
    const auto isStructured = [](const OrderedJson& element) { return element.is_structured(); };
    if (value.is_array() && std::none_of(value.begin(), value.end(), isStructured)) {
        out += "[";
        for (std::size_t index = 0; index < value.size(); ++index) {
            if (index > 0) out += ", ";
            out += value[index].dump();
        }
        out += "]";
        return;
    }
    if (!value.is_structured() || value.empty()) {
        out += value.dump();
        return;
    }
    const std::string inner(indent + 2, ' ');
    out += value.is_object() ? "{\n" : "[\n";
    bool first = true;
    for (const auto& [key, child] : value.items()) {
        out += first ? inner : ",\n" + inner;
        first = false;
        if (value.is_object()) out += OrderedJson(key).dump() + ": ";
        appendReadable(out, child, indent + 2);
    }
    out += "\n" + std::string(indent, ' ') + (value.is_object() ? "}" : "]");
}

void writeBytes(const std::filesystem::path& target, const std::vector<std::uint8_t>& bytes) {
    writeFileAtomically(target, std::as_bytes(std::span(bytes)));
}

// float32 x, y, z per node, little-endian.
void writeCoordinates(const std::filesystem::path& target, const StructuredGrid& grid) {
    std::vector<std::uint8_t> bytes;
    bytes.reserve(grid.nodes->size() * 12);
    for (const glm::vec3& node : *grid.nodes)
        for (int axis = 0; axis < 3; ++axis) {
            const auto bits = std::bit_cast<std::uint32_t>(node[axis]);
            for (int shift = 0; shift < 32; shift += 8) bytes.push_back(std::uint8_t(bits >> shift));
        }
    writeBytes(target, bytes);
}

// The coordinates file of a structured time-step: one per distinct node array, written once.
std::string coordinatesFileOf(const RawTimeStep& step, const std::filesystem::path& directory,
                              std::vector<const std::vector<glm::vec3>*>& written) {
    if (!step.structured) return {};
    const auto* nodes = step.structured->nodes.get();
    auto known = std::find(written.begin(), written.end(), nodes);
    const std::size_t index = std::size_t(known - written.begin());
    const std::string name = "grid" + std::string(index < 10 ? "0" : "") + std::to_string(index) + ".xyz.f32";
    if (known == written.end()) {
        writeCoordinates(directory / name, *step.structured);
        written.push_back(nodes);
    }
    return name;
}

}  // namespace

void writeSeries(const RawSeries& series, const std::filesystem::path& directory) {
    checkWritable(series);
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) throwInputError(directory, "", "cannot create the dataset folder: " + error.message());

    OrderedJson manifest;
    manifest["format"] = "tstyles-series";
    manifest["version"] = 1;
    manifest["name"] = series.name;
    manifest["value_range"] = OrderedJson::array({series.valueRange[0], series.valueRange[1]});
    if (series.missingValue) {
        // JSON has no NaN: the manifest spells that marker as a string.
        if (std::isnan(*series.missingValue)) manifest["missing_value"] = "NaN";
        else manifest["missing_value"] = *series.missingValue;
    }
    if (series.time.unit != TimeUnit::None) {
        manifest["time_units"] = toCfUnits(series.time);
        manifest["calendar"] = toString(series.time.calendar);
        if (series.time.climatology) manifest["climatology"] = true;
    }
    if (series.axes != std::array<SpatialAxis, 3>{}) {
        manifest["axes"] = OrderedJson::array();
        for (const SpatialAxis& axis : series.axes) {
            OrderedJson entry = {{"name", axis.name}, {"unit", axis.unit}, {"direction", toString(axis.direction)}};
            if (axis.negated) entry["negated"] = true;
            manifest["axes"].push_back(std::move(entry));
        }
    }
    manifest["time_steps"] = OrderedJson::array();
    std::vector<const std::vector<glm::vec3>*> writtenGrids;
    for (std::size_t index = 0; index < series.steps.size(); ++index) {
        const RawTimeStep& step = series.steps[index];
        const std::string stem = stepFileStem(index, series.steps.size());
        writeBytes(directory / (stem + ".raw"), step.bytes);
        if (step.mask) writeBytes(directory / (stem + "_mask.raw"), *step.mask);
        const std::string coordinatesFile = coordinatesFileOf(step, directory, writtenGrids);
        manifest["time_steps"].push_back(stepJson(step, stem, coordinatesFile));
    }
    std::string text;
    appendReadable(text, manifest, 0);
    writeFileAtomically(directory / "series.json", std::string_view(text + "\n"));
}

}  // namespace tstyles
