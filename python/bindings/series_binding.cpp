// tstyles._native.Series: a loaded series, shared with the renderers that show it, and the ways to
// make one (arrays, files). The friendly argument handling lives in python/tstyles/series.py.
#include <cmath>
#include <map>
#include <memory>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "array_series.h"
#include "bindings.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/isolated_reading.h"
#include "tstyles/data/reader_option_table.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/data/series_summary.h"
#include "tstyles/data/temporal_probe.h"

namespace py = pybind11;

namespace tstyles::python {
namespace {

CfAttributes attributesFrom(const py::dict& attributes) {
    auto text = [&](const char* key) {
        return attributes.contains(key) ? py::str(attributes[key]).cast<std::string>() : std::string();
    };
    return {text("units"), text("standard_name"), text("axis"), text("positive")};
}

AxisNodes axisNodesFrom(const py::dict& axis) {
    AxisNodes nodes;
    nodes.name = axis["name"].cast<std::string>();
    if (!axis["coordinates"].is_none()) nodes.coordinates = axis["coordinates"].cast<std::vector<double>>();
    else nodes.spacing = axis["spacing"].cast<double>();
    nodes.attributes = attributesFrom(axis["attributes"].cast<py::dict>());
    return nodes;
}

ArrayStep arrayStepFrom(const py::dict& step) {
    ArrayStep result;
    result.values = step["values"].cast<py::array>();
    if (!step["mask"].is_none()) result.mask = step["mask"].cast<py::array>();
    result.time = step["time"].cast<double>();
    const auto axes = step["axes"].cast<std::vector<py::dict>>();
    for (std::size_t axis = 0; axis < 3; ++axis) result.axes[axis] = axisNodesFrom(axes.at(axis));
    const auto origin = step["origin"].cast<std::array<double, 3>>();
    result.origin = {origin[0], origin[1], origin[2]};
    if (!step["rotation"].is_none()) {
        const auto [axis, angle] = step["rotation"].cast<std::pair<std::array<double, 3>, double>>();
        AxisAngle rotation{{axis[0], axis[1], axis[2]}, angle};
        if (!(glm::length(rotation.axis) > 0.0)) throwInputError("", "rotation", "rotation axis must not be zero");
        result.rotation = fromAxisAngle(rotation);
    }
    return result;
}

std::array<SpatialAxis, 3> spatialAxesFrom(const std::vector<py::dict>& axes, const std::string& source) {
    if (axes.size() != 3)
        throwInputError(source, "axes", "expected three axes (x, y, z), got " + std::to_string(axes.size()));
    std::array<SpatialAxis, 3> result;
    for (std::size_t index = 0; index < 3; ++index) {
        const py::dict& axis = axes[index];
        if (axis.contains("name")) result[index].name = axis["name"].cast<std::string>();
        if (axis.contains("unit")) result[index].unit = axis["unit"].cast<std::string>();
        if (axis.contains("direction")) {
            const std::string direction = axis["direction"].cast<std::string>();
            const auto parsed = axisDirectionFromString(direction);
            if (!parsed)
                throwInputError(source, "axes[" + std::to_string(index) + "].direction",
                                "unknown direction \"" + direction +
                                    "\"; allowed: east, west, north, south, up, down, right, left, anterior, "
                                    "posterior, superior, inferior, unknown");
            result[index].direction = *parsed;
        }
    }
    return result;
}

SharedSeries buildSeries(const py::dict& spec) {
    ArraySeries input;
    input.source = spec["source"].cast<std::string>();
    input.format = spec["format"].cast<std::string>();
    input.name = spec["name"].cast<std::string>();
    input.valueUnit = spec["value_unit"].cast<std::string>();
    if (!spec["axes"].is_none()) input.axes = spatialAxesFrom(spec["axes"].cast<std::vector<py::dict>>(), input.source);
    input.time = parseTimeUnits(spec["time_units"].cast<std::string>(), spec["calendar"].cast<std::string>(),
                                input.source, "time");
    for (const py::handle step : spec["steps"].cast<py::list>()) input.steps.push_back(arrayStepFrom(step.cast<py::dict>()));
    input.packing.missingValues = spec["missing_values"].cast<std::vector<double>>();
    input.packing.scale = spec["scale"].cast<double>();
    input.packing.offset = spec["offset"].cast<double>();
    if (!spec["value_range"].is_none()) input.valueRange = spec["value_range"].cast<std::array<double, 2>>();
    input.precision = parseDensityPrecision(spec["precision"].cast<std::string>(), "precision");
    return std::make_shared<const Series>(buildArraySeries(input));
}

// The reading options, keyed by their Python keywords and given as the texts the command line takes
// (series.py turns slices and tuples into them), through the reader options' table, so that a
// problem reads as it would there.
SharedSeries openFiles(const std::vector<std::filesystem::path>& inputs, const std::map<std::string, std::vector<std::string>>& options) {
    ReaderOptionTexts texts;
    for (const auto& [keyword, values] : options) {
        const ReaderOptionLine* line = readerOptionNamed(keyword);
        if (line == nullptr || line->python != keyword) throwInputError("", keyword, "is not a reader option");
        texts[std::string(line->key)] = values;
    }
    if (inputs.empty()) throwInputError("", "path", "names no file");
    return std::make_shared<const Series>(openSeriesIsolated(inputs, readOptionsFrom(texts)));
}

// The table for series.py: each option's keyword, command-line spelling, kind, default and help.
py::list readerOptionTable() {
    static const char* const kKindNames[] = {"text",  "flag",        "whole-number", "number", "choice",
                                             "steps", "value-range", "dims",         "memory", "files"};
    static_assert(std::size(kKindNames) == std::size_t(ReaderOptionKind::Files) + 1, "a name per kind");
    py::list lines;
    for (const ReaderOptionLine& line : readerOptionLines()) {
        py::dict entry;
        entry["keyword"] = std::string(line.python);
        entry["option"] = std::string(line.cli);
        entry["kind"] = kKindNames[int(line.kind)];
        entry["value"] = std::string(line.valueName);
        entry["bounds"] = readerOptionBounds(line);
        entry["default"] = std::string(line.defaultText);
        entry["help"] = std::string(line.help);
        lines.append(entry);
    }
    return lines;
}

py::dict stepInfo(const Series& series, std::size_t index) {
    if (index >= series.size()) throw py::index_error("time-step " + std::to_string(index) + " of " +
                                                      std::to_string(series.size()));
    const TimeStep& step = series.steps[index];
    py::dict info;
    info["time"] = step.time;
    info["grid"] = gridTypeName(step.grid);
    const glm::ivec3 dims = step.dims();
    info["dims"] = py::make_tuple(dims.x, dims.y, dims.z);
    if (const auto* grid = std::get_if<RectilinearGrid>(&step.grid)) {
        info["spacing"] = py::make_tuple(grid->spacing.x, grid->spacing.y, grid->spacing.z);
        py::dict positions;
        for (int axis = 0; axis < 3; ++axis)
            if (grid->isUneven(axis)) positions[py::str(std::string(1, "xyz"[axis]))] = grid->axisPositions[std::size_t(axis)];
        info["positions"] = positions;
    }
    const glm::dvec3 origin = step.placement.origin;
    info["origin"] = py::make_tuple(origin.x, origin.y, origin.z);
    const AxisAngle rotation = toAxisAngle(step.placement.rotation);
    info["rotation"] = py::make_tuple(py::make_tuple(rotation.axis.x, rotation.axis.y, rotation.axis.z), rotation.angleDeg);
    info["raw_range"] = py::make_tuple(step.rawRange[0], step.rawRange[1]);
    info["has_mask"] = step.mask.has_value();
    return info;
}

// A read-only (z, y, x) view of a time-step's densities or mask; the view keeps the series alive.
template <typename T>
py::array stepView(const py::object& owner, const std::vector<T>& values, const glm::ivec3& dims) {
    const std::vector<py::ssize_t> shape{dims.z, dims.y, dims.x};
    const std::vector<py::ssize_t> strides{py::ssize_t(sizeof(T)) * dims.x * dims.y, py::ssize_t(sizeof(T)) * dims.x,
                                           py::ssize_t(sizeof(T))};
    py::array view(py::dtype::of<T>(), shape, strides, values.data(), owner);
    py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return view;
}

py::list axesOf(const Series& series) {
    py::list axes;
    for (const SpatialAxis& axis : series.axes) {
        py::dict entry;
        entry["name"] = axis.name;
        entry["unit"] = axis.unit;
        entry["direction"] = toString(axis.direction);
        axes.append(entry);
    }
    return axes;
}

}  // namespace

void bindSeries(py::module_& module) {
    py::class_<SeriesHandle>(module, "Series")
        .def_property_readonly("name", [](const SeriesHandle& s) { return s.series->name; })
        .def("__len__", [](const SeriesHandle& s) { return s.series->size(); })
        .def_property_readonly("source", [](const SeriesHandle& s) { return s.series->manifestPath.string(); })
        .def_property_readonly("source_format", [](const SeriesHandle& s) { return s.series->sourceFormat; })
        .def_property_readonly("times", [](const SeriesHandle& s) {
            std::vector<double> times;
            for (const TimeStep& step : s.series->steps) times.push_back(step.time);
            return times;
        })
        .def_property_readonly("time_units", [](const SeriesHandle& s) { return toCfUnits(s.series->time); })
        .def_property_readonly("calendar", [](const SeriesHandle& s) { return toString(s.series->time.calendar); })
        .def_property_readonly("time_labels", [](const SeriesHandle& s) {
            std::vector<double> times;
            for (const TimeStep& step : s.series->steps) times.push_back(step.time);
            return formatTimes(times, s.series->time);
        })
        .def_property_readonly("value_range", [](const SeriesHandle& s) { return s.series->valueRange; })
        .def_property_readonly("value_unit", [](const SeriesHandle& s) { return s.series->valueUnit; })
        .def_property_readonly("precision", [](const SeriesHandle& s) { return precisionBits(s.series->precision); })
        .def_property_readonly("axes", [](const SeriesHandle& s) { return axesOf(*s.series); })
        .def("step", [](const SeriesHandle& s, std::size_t index) { return stepInfo(*s.series, index); })
        .def("density", [](const py::object& self, std::size_t index) {
            const Series& series = *self.cast<const SeriesHandle&>().series;
            if (index >= series.size()) throw py::index_error("no time-step " + std::to_string(index));
            return stepView(self, series.steps[index].density, series.steps[index].dims());
        })
        .def("mask", [](const py::object& self, std::size_t index) -> py::object {
            const Series& series = *self.cast<const SeriesHandle&>().series;
            if (index >= series.size()) throw py::index_error("no time-step " + std::to_string(index));
            const TimeStep& step = series.steps[index];
            if (!step.mask) return py::none();
            return stepView(self, *step.mask, step.dims());
        })
        .def("describe", [](const SeriesHandle& s) { return describeSeries(*s.series); })
        .def("values_at", [](const SeriesHandle& s, double x, double y, double z) {
            // (x, y, z) in the file's coordinates (a pressure level as the file counts it); NaN
            // where a time-step's grid does not reach the place or has no data there.
            std::vector<double> values;
            for (const auto& value : TemporalProbe(*s.series).valuesAt(worldCoordinatesOf(*s.series, {x, y, z})))
                values.push_back(value ? *value : std::nan(""));
            return values;
        });

    module.def("build_series", [](const py::dict& spec) { return SeriesHandle{buildSeries(spec)}; });
    module.def("reader_options", &readerOptionTable);
    module.def("open_series", [](const std::vector<std::filesystem::path>& inputs,
                                 const std::map<std::string, std::vector<std::string>>& options) {
        return SeriesHandle{openFiles(inputs, options)};
    });
}

}  // namespace tstyles::python
