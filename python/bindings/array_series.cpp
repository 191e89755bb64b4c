// Arrays to a Series through the readers' assembly (array_series.h).
#include "array_series.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>

#include "series_assembly.h"
#include "tstyles/core/errors.h"

namespace py = pybind11;

namespace tstyles::python {
namespace {

std::string numberText(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string shapeText(const py::array& array) {
    std::string text = "(";
    for (py::ssize_t axis = 0; axis < array.ndim(); ++axis)
        text += (axis ? ", " : "") + std::to_string(array.shape(axis));
    return text + (array.ndim() == 1 ? ",)" : ")");
}

// Our value type for the array's dtype; numpy's other types are refused rather than narrowed.
ValueType valueTypeOf(const py::array& array, const std::string& source, const std::string& field) {
    const char kind = array.dtype().kind();
    const py::ssize_t size = array.itemsize();
    if (kind == 'u' && size == 1) return ValueType::UInt8;
    if (kind == 'u' && size == 2) return ValueType::UInt16;
    if (kind == 'i' && size == 1) return ValueType::Int8;
    if (kind == 'i' && size == 2) return ValueType::Int16;
    if (kind == 'i' && size == 4) return ValueType::Int32;
    if (kind == 'f' && size == 4) return ValueType::Float32;
    if (kind == 'f' && size == 8) return ValueType::Float64;
    throwInputError(source, field,
                    "dtype " + std::string(py::str(array.dtype())) +
                        " is not supported (uint8, uint16, int8, int16, int32, float32, float64): convert it with "
                        ".astype(numpy.float32)");
}

// The raw values of one time-step, x fastest, read through the array's strides (no copy of the
// array first); NaN and declared markers become missing, the rest are unpacked.
template <typename T>
std::vector<float> unpackValues(const py::array& array, const ArrayPacking& packing, const std::string& source,
                                std::size_t step) {
    const auto view = array.unchecked<T, 3>();
    const py::ssize_t nz = view.shape(0), ny = view.shape(1), nx = view.shape(2);
    std::vector<float> values(std::size_t(nx) * std::size_t(ny) * std::size_t(nz));
    const bool unpack = packing.scale != 1.0 || packing.offset != 0.0;
    std::size_t index = 0;
    for (py::ssize_t z = 0; z < nz; ++z)
        for (py::ssize_t y = 0; y < ny; ++y)
            for (py::ssize_t x = 0; x < nx; ++x, ++index) {
                const T raw = view(z, y, x);
                bool missing = std::isnan(double(raw));
                // Markers compare in the array's own precision, as the NetCDF reader compares them.
                for (double marker : packing.missingValues) {
                    if constexpr (std::is_floating_point_v<T>) missing = missing || raw == T(marker);
                    else missing = missing || double(raw) == marker;
                }
                if (missing) {
                    values[index] = missingDensity();
                    continue;
                }
                const float value = unpack ? float(double(raw) * packing.scale + packing.offset) : float(raw);
                if (std::isinf(value))
                    throwInputError(source, "",
                                    "time-step " + std::to_string(step) + " holds Inf at voxel (x, y, z) = (" +
                                        std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
                                        "): only NaN (or a declared fill value) marks missing data");
                values[index] = value;
            }
    return values;
}

std::vector<float> readValues(const py::array& array, ValueType type, const ArrayPacking& packing,
                              const std::string& source, std::size_t step) {
    switch (type) {
        case ValueType::UInt8: return unpackValues<std::uint8_t>(array, packing, source, step);
        case ValueType::UInt16: return unpackValues<std::uint16_t>(array, packing, source, step);
        case ValueType::Int8: return unpackValues<std::int8_t>(array, packing, source, step);
        case ValueType::Int16: return unpackValues<std::int16_t>(array, packing, source, step);
        case ValueType::Int32: return unpackValues<std::int32_t>(array, packing, source, step);
        case ValueType::Float32: return unpackValues<float>(array, packing, source, step);
        case ValueType::Float64: return unpackValues<double>(array, packing, source, step);
    }
    return {};
}

glm::ivec3 gridDimsOf(const py::array& values, const std::string& source, const std::string& field) {
    if (values.ndim() != 3)
        throwInputError(source, field, "expected a 3D array (z, y, x), got shape " + shapeText(values));
    const glm::ivec3 dims(int(values.shape(2)), int(values.shape(1)), int(values.shape(0)));
    if (glm::any(glm::lessThan(dims, glm::ivec3(2))))
        throwInputError(source, field,
                        "shape " + shapeText(values) + ": a grid needs two samples along each axis to span a box");
    return dims;
}

// The grid and placement of one time-step, and which axes its values run against.
struct PlacedGrid {
    RectilinearGrid grid;
    Placement placement;
    std::array<bool, 3> reversed{false, false, false};
    std::array<SpatialAxis, 3> meaning;
};

PlacedGrid placeGrid(const ArrayStep& step, const glm::ivec3& dims, const std::string& source) {
    PlacedGrid placed;
    placed.grid.dims = dims;
    placed.placement.origin = step.origin;
    placed.placement.rotation = step.rotation;
    for (int axis = 0; axis < 3; ++axis) {
        const AxisNodes& nodes = step.axes[std::size_t(axis)];
        placed.meaning[std::size_t(axis)].name = nodes.name;
        if (!nodes.coordinates) {
            if (!std::isfinite(nodes.spacing) || nodes.spacing <= 0.0)
                throwInputError(source, "spacing", "must be positive, found " + numberText(nodes.spacing));
            placed.grid.spacing[axis] = nodes.spacing;
            continue;
        }
        if (nodes.coordinates->size() != std::size_t(dims[axis]))
            throwInputError(source, nodes.name,
                            "expected " + std::to_string(dims[axis]) +
                                " node positions (one per sample along the axis), found " +
                                std::to_string(nodes.coordinates->size()));
        const CfSpatialAxis frame = cfSpatialAxis(nodes.name, nodes.attributes, *nodes.coordinates, source);
        placed.grid.spacing[axis] = frame.spacing;
        placed.grid.axisPositions[std::size_t(axis)] = frame.positions;
        placed.placement.origin[axis] += frame.origin;
        placed.reversed[std::size_t(axis)] = frame.reversed;
        placed.meaning[std::size_t(axis)] = frame.meaning;
    }
    return placed;
}

void requireIncreasingStepTimes(const ArraySeries& input) {
    for (std::size_t index = 0; index < input.steps.size(); ++index) {
        const double time = input.steps[index].time;
        const std::string field = "times[" + std::to_string(index) + "]";
        if (!std::isfinite(time)) throwInputError(input.source, field, "expected a finite number, found " + numberText(time));
        if (index > 0 && !(time > input.steps[index - 1].time))
            throwInputError(input.source, field,
                            "times must be strictly increasing: " + numberText(time) + " follows " +
                                numberText(input.steps[index - 1].time));
    }
}

void requireValueRange(const ArraySeries& input) {
    if (!input.valueRange) return;
    const auto [low, high] = *input.valueRange;
    if (!std::isfinite(low) || !std::isfinite(high) || !(low < high))
        throwInputError(input.source, "value_range",
                        "expected finite [low, high] with low less than high, found [" + numberText(low) + ", " +
                            numberText(high) + "]");
}

// The mask's bytes, x fastest, reversed along the axes its values are reversed along.
std::vector<std::uint8_t> maskBytes(const py::array& mask, const py::array& values, const std::string& source,
                                    std::size_t step, const std::array<bool, 3>& reversed) {
    const std::string field = "masks[" + std::to_string(step) + "]";
    if (mask.ndim() != 3 || mask.shape(0) != values.shape(0) || mask.shape(1) != values.shape(1) ||
        mask.shape(2) != values.shape(2))
        throwInputError(source, field, "shape " + shapeText(mask) + " differs from the values' " + shapeText(values));
    const char kind = mask.dtype().kind();
    if (mask.itemsize() != 1 || (kind != 'u' && kind != 'b'))
        throwInputError(source, field, "dtype " + std::string(py::str(mask.dtype())) + ": a mask is uint8 or bool");
    const auto view = mask.unchecked<std::uint8_t, 3>();
    std::vector<std::uint8_t> bytes;
    bytes.reserve(std::size_t(mask.size()));
    for (py::ssize_t z = 0; z < view.shape(0); ++z)
        for (py::ssize_t y = 0; y < view.shape(1); ++y)
            for (py::ssize_t x = 0; x < view.shape(2); ++x) bytes.push_back(view(z, y, x));
    const glm::ivec3 dims(int(mask.shape(2)), int(mask.shape(1)), int(mask.shape(0)));
    for (int axis = 0; axis < 3; ++axis) {
        if (!reversed[std::size_t(axis)]) continue;
        std::vector<float> asFloat(bytes.begin(), bytes.end());
        reverseGridAxis(asFloat, dims, axis);
        for (std::size_t voxel = 0; voxel < bytes.size(); ++voxel) bytes[voxel] = std::uint8_t(asFloat[voxel]);
    }
    return bytes;
}

}  // namespace

Series buildArraySeries(const ArraySeries& input) {
    if (input.steps.empty()) throwInputError(input.source, "data", "holds no time-step");
    requireIncreasingStepTimes(input);
    requireValueRange(input);

    SourceSeries source;
    source.name = input.name;
    source.file = input.source;
    source.format = input.format;
    source.time = input.time;
    source.valueUnit = input.valueUnit;
    std::vector<std::array<bool, 3>> reversed;
    std::vector<ValueType> types;
    std::vector<std::optional<std::vector<std::uint8_t>>> masks;
    for (std::size_t index = 0; index < input.steps.size(); ++index) {
        const ArrayStep& step = input.steps[index];
        const std::string field = "data[" + std::to_string(index) + "]";
        const glm::ivec3 dims = gridDimsOf(step.values, input.source, field);
        types.push_back(valueTypeOf(step.values, input.source, field));
        const PlacedGrid placed = placeGrid(step, dims, input.source);
        if (index == 0) source.axes = input.axes.value_or(placed.meaning);
        reversed.push_back(placed.reversed);
        if (step.mask) masks.push_back(maskBytes(*step.mask, step.values, input.source, index, placed.reversed));
        else masks.emplace_back();
        source.steps.push_back({step.time, placed.grid, placed.placement, types.back(), input.source});
    }
    source.readStep = [&input, &reversed, &types](std::size_t index) {
        const ArrayStep& step = input.steps[index];
        std::vector<float> values = readValues(step.values, types[index], input.packing, input.source, index);
        const glm::ivec3 dims(int(step.values.shape(2)), int(step.values.shape(1)), int(step.values.shape(0)));
        for (int axis = 0; axis < 3; ++axis)
            if (reversed[index][std::size_t(axis)]) reverseGridAxis(values, dims, axis);
        return values;
    };

    ReadOptions options;
    options.valueRange = input.valueRange;
    options.precision = input.precision;
    Series series = toDensity(assembleRawSeries(source, options));
    series.sourceFormat = input.format;
    series.precision = input.precision;
    for (std::size_t index = 0; index < series.steps.size(); ++index) series.steps[index].mask = std::move(masks[index]);
    return series;
}

}  // namespace tstyles::python
