// NetCDF through libnetcdf: pick the variable, find time, read coordinates, unpack values.
#include "netcdf_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>

#include <netcdf.h>

#include "finite_values.h"
#include "netcdf_file.h"
#include "series_assembly.h"
#include "tstyles/core/errors.h"

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

std::string lowercase(std::string text) {
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// CF: a coordinate variable with axis = "T" or units "<unit> since <date>"; else a name like time.
bool looksLikeTime(const NetcdfFile& nc, const std::string& dimension) {
    if (const auto coordinate = nc.findVariable(dimension)) {
        if (lowercase(nc.textAttribute(*coordinate, "axis").value_or("")) == "t") return true;
        if (nc.textAttribute(*coordinate, "units").value_or("").find(" since ") != std::string::npos) return true;
    }
    const std::string name = lowercase(dimension);
    return name == "t" || name.find("time") != std::string::npos;
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
struct AxisFrame {
    double origin = 0.0;
    double spacing = 1.0;
    std::vector<double> positions;  // uneven axes only
    bool reversed = false;
    SpatialAxis meaning;
};

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

bool isPressureUnit(const std::string& unit) {
    for (const char* name : {"pa", "hpa", "kpa", "mbar", "millibar", "millibars", "bar", "dbar", "decibar", "atm"})
        if (unit == name) return true;
    return false;
}

// CF: longitude and latitude by standard_name or units (degrees_east, degrees_north), the vertical
// by axis = "Z", a vertical standard_name, a pressure unit or a `positive` attribute. Vertical
// coordinates that grow downward (depth, pressure) are negated by the reader, so +axis is up.
AxisDirection cfDirection(const NetcdfFile& nc, int id, bool& down) {
    const std::string units = lowercase(nc.textAttribute(id, "units").value_or(""));
    const std::string standardName = lowercase(nc.textAttribute(id, "standard_name").value_or(""));
    const std::string axis = lowercase(nc.textAttribute(id, "axis").value_or(""));
    const std::string positive = lowercase(nc.textAttribute(id, "positive").value_or(""));
    const bool pressure = isPressureUnit(units) || standardName.find("pressure") != std::string::npos;
    down = positive == "down" || (positive.empty() && pressure);
    if (standardName == "longitude" || startsWith(units, "degrees_e") || startsWith(units, "degree_e") ||
        units == "degreese")
        return AxisDirection::East;
    if (standardName == "latitude" || startsWith(units, "degrees_n") || startsWith(units, "degree_n") ||
        units == "degreesn")
        return AxisDirection::North;
    const bool vertical = axis == "z" || !positive.empty() || pressure || standardName == "depth" ||
                          standardName == "altitude" || standardName == "height" ||
                          standardName.find("model_level") != std::string::npos;
    return vertical ? AxisDirection::Up : AxisDirection::Unknown;
}

AxisFrame axisFrame(const NetcdfFile& nc, const NetcdfDimension& dimension, bool indexAxes) {
    AxisFrame frame;
    frame.meaning.name = dimension.name;
    const auto id = nc.findVariable(dimension.name);
    if (!id || !nc.isCoordinateVariable(*id)) return frame;
    bool down = false;
    frame.meaning.direction = cfDirection(nc, *id, down);
    if (indexAxes) {
        // Unit spacing in index order, nothing negated or reversed: +axis follows the file's order.
        const std::vector<double> values = nc.readAll(*id);
        const bool decreasing = values.size() >= 2 && values[1] < values[0];
        if (down != decreasing) frame.meaning.direction = opposite(frame.meaning.direction);
        return frame;
    }
    frame.meaning.unit = nc.textAttribute(*id, "units").value_or("");
    std::vector<double> world = nc.readAll(*id);
    for (double& value : world) {
        if (!std::isfinite(value))
            throwInputError(nc.path(), dimension.name, "coordinate variable holds a non-finite value");
        if (down) value = -value;
    }
    if (world.size() >= 2 && world[1] < world[0]) {
        std::reverse(world.begin(), world.end());
        frame.reversed = true;
    }
    for (std::size_t index = 1; index < world.size(); ++index)
        if (!(world[index] > world[index - 1]))
            throwInputError(nc.path(), dimension.name, "coordinate variable is not strictly monotonic");
    frame.origin = world.front();
    const double extent = world.back() - world.front();
    frame.spacing = extent / double(world.size() - 1);
    bool even = true;
    for (std::size_t index = 1; index < world.size(); ++index)
        even = even && std::abs((world[index] - world[index - 1]) - frame.spacing) <= 1e-6 * frame.spacing;
    if (!even)
        for (double value : world) frame.positions.push_back(value - world.front());
    return frame;
}

// Reverses the values along one grid axis (the file stores that axis against its coordinate).
void reverseAxis(std::vector<float>& values, const glm::ivec3& dims, int axis) {
    const std::size_t stride[3] = {1, std::size_t(dims.x), std::size_t(dims.x) * std::size_t(dims.y)};
    const std::size_t count = std::size_t(dims[axis]);
    for (std::size_t index = 0; index < values.size(); ++index) {
        const std::size_t position = (index / stride[axis]) % count;
        if (position < count / 2) std::swap(values[index], values[index + (count - 1 - 2 * position) * stride[axis]]);
    }
}

// CF: the time coordinate's units ("days since 1950-01-01") and calendar.
TimeAxis timeAxisOf(const NetcdfFile& nc, const NetcdfVariable& variable, int timeDimension) {
    if (timeDimension < 0) return {};
    const std::string name = variable.dimensions[std::size_t(timeDimension)].name;
    const auto id = nc.findVariable(name);
    if (!id || !nc.isCoordinateVariable(*id)) return {};
    return parseTimeUnits(nc.textAttribute(*id, "units").value_or(""), nc.textAttribute(*id, "calendar").value_or(""),
                          nc.path(), name);
}

std::vector<double> stepTimes(const NetcdfFile& nc, const NetcdfVariable& variable, int timeDimension) {
    if (timeDimension < 0) return {0.0};
    const NetcdfDimension& dimension = variable.dimensions[std::size_t(timeDimension)];
    requireStepCount(nc.path(), dimension.name, dimension.length);
    std::vector<double> times(dimension.length);
    for (std::size_t index = 0; index < times.size(); ++index) times[index] = double(index);
    const auto id = nc.findVariable(dimension.name);
    if (!id || !nc.isCoordinateVariable(*id)) return times;
    const std::vector<double> values = nc.readAll(*id);
    for (std::size_t index = 0; index < values.size(); ++index)
        if (!std::isfinite(values[index]) || (index > 0 && !(values[index] > values[index - 1])))
            throwInputError(nc.path(), dimension.name, "time coordinate is not finite and strictly increasing");
    return values;
}

}  // namespace

SourceSeries openNetcdf(const std::filesystem::path& file, const ReadOptions& options) {
    auto nc = std::make_shared<const NetcdfFile>(file);
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
    std::array<AxisFrame, 3> frames;
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
    source.time = timeAxisOf(*nc, variable, timeDimension);
    source.valueUnit = nc->textAttribute(variable.id, "units").value_or("");
    for (double time : stepTimes(*nc, variable, timeDimension)) {
        source.steps.push_back({time, grid, placement, type, file});
    }
    source.readStep = [nc, variable, timeDimension, dims, frames, packing](std::size_t index) {
        NetcdfVolume volume = nc->readVolume(variable, timeDimension, index, packing);
        requireFiniteValues(volume.values, dims, nc->path(), index, "declare it with _FillValue or missing_value");
        std::vector<float> values = std::move(volume.values);
        for (std::size_t voxel = 0; voxel < values.size(); ++voxel)
            if (volume.missing[voxel]) values[voxel] = missingDensity();
        for (int axis = 0; axis < 3; ++axis)
            if (frames[std::size_t(axis)].reversed) reverseAxis(values, dims, axis);
        return values;
    };
    return source;
}

bool hasNetcdfSignature(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[8] = {};
    in.read(magic, 8);
    if (!in) return false;
    if (magic[0] == 'C' && magic[1] == 'D' && magic[2] == 'F' && (magic[3] == 1 || magic[3] == 2 || magic[3] == 5))
        return true;
    return std::string(magic + 1, 3) == "HDF" && static_cast<unsigned char>(magic[0]) == 0x89;
}

}  // namespace tstyles
