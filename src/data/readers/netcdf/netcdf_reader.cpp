// NetCDF through libnetcdf: pick the variable, find time, read coordinates, unpack values.
#include "netcdf_reader.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <netcdf.h>

#include "../file_magic.h"
#include "../infinite_values.h"
#include "netcdf_file.h"
#include "../series_assembly.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/cf_conventions.h"

namespace tstyles {
namespace {

// Far beyond any volume a GPU holds (a 3D texture is at most 16384 wide), small enough for int.
constexpr std::size_t kMaxAxisSamples = std::size_t(1) << 20;

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text.empty() ? "none" : text;
}

// The variables that could be a volume series: three or four dimensions, not a coordinate variable.
std::vector<std::string> candidateVariables(const NetcdfFile& nc) {
    std::vector<std::string> names;
    for (int id : nc.variableIds()) {
        const NetcdfVariable variable = nc.variable(id);
        if ((variable.dimensions.size() == 3 || variable.dimensions.size() == 4) && !nc.isCoordinateVariable(id))
            names.push_back(variable.name);
    }
    return names;
}

NetcdfVariable chooseVariable(const NetcdfFile& nc, const std::string& wanted) {
    const std::vector<std::string> candidates = candidateVariables(nc);
    if (!wanted.empty()) {
        const auto id = nc.findVariable(wanted);
        if (!id)
            throwInputError(nc.path(), "--var",
                            "no variable named \"" + wanted + "\" (volume variables in this file: " +
                                joined(candidates) + ")");
        return nc.variable(*id);
    }
    if (candidates.size() != 1)
        throwInputError(nc.path(), "--var",
                        candidates.empty()
                            ? "the file holds no variable of three or four dimensions"
                            : "the file holds " + std::to_string(candidates.size()) + " volume variables (" +
                                  joined(candidates) + "): choose one with --var");
    return nc.variable(*nc.findVariable(candidates[0]));
}

// The CF attributes of a coordinate variable.
CfAttributes cfAttributes(const NetcdfFile& nc, int id) {
    return {nc.textAttribute(id, "units").value_or(""), nc.textAttribute(id, "standard_name").value_or(""),
            nc.textAttribute(id, "axis").value_or(""), nc.textAttribute(id, "positive").value_or("")};
}

bool looksLikeTime(const NetcdfFile& nc, const std::string& dimension) {
    if (const auto coordinate = nc.findVariable(dimension)) {
        const CfAttributes attributes = cfAttributes(nc, *coordinate);
        return cfLooksLikeTime(dimension, &attributes);
    }
    return cfLooksLikeTime(dimension, nullptr);
}

int findTimeDimension(const NetcdfFile& nc, const NetcdfVariable& variable, const ReadOptions& options) {
    const auto& dims = variable.dimensions;
    if (!options.timeDimension.empty()) {
        const auto found = std::find_if(dims.begin(), dims.end(),
                                        [&](const NetcdfDimension& d) { return d.name == options.timeDimension; });
        if (found == dims.end())
            throwInputError(nc.path(), "--time-dim",
                            "variable " + variable.name + " has no dimension \"" + options.timeDimension + "\"");
        return int(found - dims.begin());
    }
    for (std::size_t index = 0; index < dims.size(); ++index)
        if (looksLikeTime(nc, dims[index].name)) return int(index);
    return -1;
}

std::string dimensionList(const NetcdfVariable& variable) {
    std::vector<std::string> names;
    for (const auto& d : variable.dimensions) names.push_back(d.name + " = " + std::to_string(d.length));
    return "(" + joined(names) + ")";
}

// One spatial axis: where its nodes are in the world, and whether the data runs against it.
CfSpatialAxis axisFrame(const NetcdfFile& nc, const NetcdfDimension& dimension, bool indexAxes) {
    const auto id = nc.findVariable(dimension.name);
    if (!id || !nc.isCoordinateVariable(*id)) {
        CfSpatialAxis frame;
        frame.meaning.name = dimension.name;
        return frame;
    }
    const CfAttributes attributes = cfAttributes(nc, *id);
    if (indexAxes) return cfIndexAxis(dimension.name, attributes, nc.readAll(*id));
    return cfSpatialAxis(dimension.name, attributes, nc.readAll(*id), nc.path());
}

// CF: the time coordinate's units ("days since 1950-01-01"; "months since 0000-01-01" as calendar
// months) and calendar, whether it is a climatology (a `climatology` attribute naming its bounds),
// and the stamps; without a coordinate variable the time-steps' indices.
struct StepTimes {
    TimeAxis axis;
    std::vector<double> times;
};

StepTimes stepTimesOf(const NetcdfFile& nc, const NetcdfVariable& variable, int timeDimension) {
    if (timeDimension < 0) return {{}, {0.0}};
    const NetcdfDimension& dimension = variable.dimensions[std::size_t(timeDimension)];
    const auto id = nc.findVariable(dimension.name);
    const bool coordinate = id && nc.isCoordinateVariable(*id);
    const std::string units = coordinate ? nc.textAttribute(*id, "units").value_or("") : "";
    const std::string calendar = coordinate ? nc.textAttribute(*id, "calendar").value_or("") : "";
    StepTimes result;
    // Months and years are read with the stamps; any other unit is checked before they are.
    const bool calendarMonths = readCalendarMonths(units, calendar, {}, nc.path(), dimension.name).has_value();
    if (coordinate && !calendarMonths) result.axis = parseTimeUnits(units, calendar, nc.path(), dimension.name);
    requireStepCount(nc.path(), dimension.name, dimension.length);
    if (!coordinate) {
        for (std::size_t index = 0; index < dimension.length; ++index) result.times.push_back(double(index));
        return result;
    }
    result.times = nc.readAll(*id);
    requireIncreasingTimes(result.times, nc.path(), dimension.name);
    if (calendarMonths) {
        CalendarMonthStamps stamps = *readCalendarMonths(units, calendar, result.times, nc.path(), dimension.name);
        result.axis = stamps.axis;
        result.times = std::move(stamps.days);
    }
    result.axis.climatology = nc.textAttribute(*id, "climatology").has_value();
    return result;
}

}  // namespace

SourceSeries openNetcdf(const std::filesystem::path& file, const ReadOptions& options) {
    auto nc = std::make_shared<const NetcdfFile>(file, options.monitor);
    const NetcdfVariable variable = chooseVariable(*nc, options.variable);
    const int timeDimension = findTimeDimension(*nc, variable, options);
    const std::size_t rank = variable.dimensions.size();
    if (rank != 3 && rank != 4)
        throwInputError(file, variable.name,
                        "has " + std::to_string(rank) + " dimensions " + dimensionList(variable) +
                            ": a volume series needs three spatial dimensions and optionally time");
    if (rank == 4 && timeDimension < 0)
        throwInputError(file, variable.name,
                        "cannot find the time dimension among " + dimensionList(variable) +
                            ": no dimension has a coordinate variable with axis = \"T\" or units \"... since ...\", "
                            "and none is named like time; name it with --time-dim");
    if (rank == 3 && timeDimension >= 0)
        throwInputError(file, variable.name,
                        "has only two spatial dimensions besides time " + dimensionList(variable) +
                            ": a volume needs three");
    const ValueType type = netcdfValueType(*nc, variable);
    const NetcdfPacking packing = nc->packing(variable);

    // Spatial dimensions slowest first (z, y, x): x is the last, fastest dimension.
    std::vector<int> spatial;
    for (int index = 0; index < int(rank); ++index)
        if (index != timeDimension) spatial.push_back(index);
    glm::ivec3 dims;
    std::array<CfSpatialAxis, 3> frames;
    for (int axis = 0; axis < 3; ++axis) {
        const NetcdfDimension& dimension = variable.dimensions[std::size_t(spatial[std::size_t(2 - axis)])];
        if (dimension.length < 2)
            throwInputError(file, variable.name,
                            "dimension " + dimension.name + " has " + std::to_string(dimension.length) +
                                " samples: each spatial axis needs at least 2");
        if (dimension.length > kMaxAxisSamples)
            throwInputError(file, variable.name,
                            "dimension " + dimension.name + " has " + std::to_string(dimension.length) +
                                " samples: too large, a spatial axis may have at most " +
                                std::to_string(kMaxAxisSamples));
        dims[axis] = int(dimension.length);
        frames[std::size_t(axis)] = axisFrame(*nc, dimension, options.indexAxes);
    }
    SourceSeries source;
    RectilinearGrid grid;
    grid.dims = dims;
    Placement placement;
    for (int axis = 0; axis < 3; ++axis) {
        source.axes[std::size_t(axis)] = frames[std::size_t(axis)].meaning;
        grid.spacing[axis] = frames[std::size_t(axis)].spacing;
        grid.axisPositions[std::size_t(axis)] = frames[std::size_t(axis)].positions;
        placement.origin[axis] = frames[std::size_t(axis)].origin;
    }

    source.name = variable.name;
    source.file = file;
    source.format = nc->formatName();
    StepTimes times = stepTimesOf(*nc, variable, timeDimension);
    source.time = times.axis;
    source.valueUnit = nc->textAttribute(variable.id, "units").value_or("");
    for (double time : times.times) {
        source.steps.push_back({time, grid, placement, type, file});
    }
    source.readStep = [nc, variable, timeDimension, dims, frames, packing](std::size_t index) {
        NetcdfVolume volume = nc->readVolume(variable, timeDimension, index, packing);
        refuseInfinities(volume.values, dims, nc->path(), index);
        std::vector<float> values = std::move(volume.values);
        for (std::size_t voxel = 0; voxel < values.size(); ++voxel)
            if (volume.missing[voxel]) values[voxel] = missingDensity();
        for (int axis = 0; axis < 3; ++axis)
            if (frames[std::size_t(axis)].reversed) reverseGridAxis(values, dims, axis);
        return values;
    };
    return source;
}

bool hasNetcdfSignature(const std::filesystem::path& file) {
    // Classic (CDF 1), 64-bit offset (2), 64-bit data (5); netCDF-4 is HDF5.
    const std::string start = fileStart(file, 8);
    if (start.size() < 8) return false;
    return hasMagicAt(start, 0, std::string_view("CDF\x01", 4)) || hasMagicAt(start, 0, std::string_view("CDF\x02", 4)) ||
           hasMagicAt(start, 0, std::string_view("CDF\x05", 4)) || hasMagicAt(start, 0, "\x89HDF");
}

}  // namespace tstyles
