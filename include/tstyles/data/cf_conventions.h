// CF conventions for coordinates, in one place for every source that carries them: the NetCDF reader
// (attributes read from the file) and the Python module (an xarray.DataArray's coords and attrs).
// What an axis means (direction, unit), where its nodes lie (origin, spacing, uneven positions),
// whether the values run against it, and which dimension is time. GL-free.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

// The attributes of a coordinate variable that CF gives meaning to, as the source spells them
// (empty: not given).
struct CfAttributes {
    std::string units;
    std::string standardName;
    std::string axis;
    std::string positive;
};

// Longitude and latitude by standard_name or units (degrees_east, degrees_north), the vertical by
// axis = "Z", a vertical standard_name, a pressure unit or a `positive` attribute. `down` is set for
// vertical coordinates that grow downward (positive = "down", or a pressure without `positive`).
AxisDirection cfDirection(const CfAttributes& attributes, bool& down);

// One spatial axis placed in the world from its coordinate values.
struct CfSpatialAxis {
    double origin = 0.0;
    double spacing = 1.0;
    std::vector<double> positions;  // grid-local node positions, uneven axes only
    bool reversed = false;          // the values run against the coordinate: reverse them (reverseGridAxis)
    SpatialAxis meaning;
};

// Coordinates that grow downward are negated, so +axis is up; decreasing coordinates are reversed
// (with the values), so nodes always increase. Evenly spaced nodes (within 1e-6 of the mean
// spacing) give a spacing, others node positions. A non-finite or non-monotonic coordinate is an
// InputError naming `source` and the axis' `name`.
CfSpatialAxis cfSpatialAxis(const std::string& name, const CfAttributes& attributes, std::vector<double> values,
                            const std::filesystem::path& source);

// Unit spacing in index order (--index-axes): nothing negated or reversed, so the direction is
// flipped where the coordinate runs against it.
CfSpatialAxis cfIndexAxis(const std::string& name, const CfAttributes& attributes, const std::vector<double>& values);

// A coordinate with axis = "T" or units "<unit> since <date>" (`attributes` null: the dimension has
// no coordinate), else a dimension named "t" or like "time".
bool cfLooksLikeTime(const std::string& dimension, const CfAttributes* attributes);

// Time stamps must be finite and strictly increasing: an InputError naming `source` and `name`.
void requireIncreasingTimes(const std::vector<double>& values, const std::filesystem::path& source,
                            const std::string& name);

// Reverses the values (x fastest) along one grid axis, for an axis that CF placement reversed.
void reverseGridAxis(std::vector<float>& values, const glm::ivec3& dims, int axis);

}  // namespace tstyles
