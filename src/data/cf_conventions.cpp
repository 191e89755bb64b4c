// CF coordinates: direction, placement and time (cf_conventions.h).
#include "tstyles/core/ascii_case.h"
#include "tstyles/data/cf_conventions.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <utility>

#include "tstyles/core/errors.h"
#include "tstyles/data/axis_nodes.h"

namespace tstyles {
namespace {

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

bool isPressureUnit(const std::string& unit) {
    for (const char* name : {"pa", "hpa", "kpa", "mbar", "millibar", "millibars", "bar", "dbar", "decibar", "atm"})
        if (unit == name) return true;
    return false;
}

}  // namespace

AxisDirection cfDirection(const CfAttributes& attributes, bool& down) {
    const std::string units = asciiLowercase(attributes.units);
    const std::string standardName = asciiLowercase(attributes.standardName);
    const std::string axis = asciiLowercase(attributes.axis);
    const std::string positive = asciiLowercase(attributes.positive);
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

CfSpatialAxis cfSpatialAxis(const std::string& name, const CfAttributes& attributes, std::vector<double> values,
                            const std::filesystem::path& source) {
    CfSpatialAxis frame;
    frame.meaning.name = name;
    bool down = false;
    frame.meaning.direction = cfDirection(attributes, down);
    frame.meaning.unit = attributes.units;
    frame.meaning.negated = down;
    for (double& value : values) {
        if (!std::isfinite(value)) throwInputError(source, name, "coordinate variable holds a non-finite value");
        if (down) value = -value;
    }
    if (values.size() >= 2 && values[1] < values[0]) {
        std::reverse(values.begin(), values.end());
        frame.reversed = true;
    }
    for (std::size_t index = 1; index < values.size(); ++index)
        if (!(values[index] > values[index - 1]))
            throwInputError(source, name, "coordinate variable is not strictly monotonic");
    AxisNodes nodes = axisNodesOf(values, 1e-6);
    frame.origin = nodes.origin;
    frame.spacing = nodes.spacing;
    frame.positions = std::move(nodes.positions);
    return frame;
}

CfSpatialAxis cfIndexAxis(const std::string& name, const CfAttributes& attributes, const std::vector<double>& values) {
    CfSpatialAxis frame;
    frame.meaning.name = name;
    bool down = false;
    frame.meaning.direction = cfDirection(attributes, down);
    const bool decreasing = values.size() >= 2 && values[1] < values[0];
    if (down != decreasing) frame.meaning.direction = opposite(frame.meaning.direction);
    return frame;
}

bool cfLooksLikeTime(const std::string& dimension, const CfAttributes* attributes) {
    if (attributes) {
        if (asciiLowercase(attributes->axis) == "t") return true;
        if (attributes->units.find(" since ") != std::string::npos) return true;
    }
    const std::string name = asciiLowercase(dimension);
    return name == "t" || name.find("time") != std::string::npos;
}

void requireIncreasingTimes(const std::vector<double>& values, const std::filesystem::path& source,
                            const std::string& name) {
    for (std::size_t index = 0; index < values.size(); ++index)
        if (!std::isfinite(values[index]) || (index > 0 && !(values[index] > values[index - 1])))
            throwInputError(source, name, "time coordinate is not finite and strictly increasing");
}

void reverseGridAxis(std::vector<float>& values, const glm::ivec3& dims, int axis) {
    const std::size_t stride[3] = {1, std::size_t(dims.x), std::size_t(dims.x) * std::size_t(dims.y)};
    const std::size_t count = std::size_t(dims[axis]);
    for (std::size_t index = 0; index < values.size(); ++index) {
        const std::size_t position = (index / stride[axis]) % count;
        if (position < count / 2) std::swap(values[index], values[index + (count - 1 - 2 * position) * stride[axis]]);
    }
}

}  // namespace tstyles
