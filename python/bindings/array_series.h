// A Series from arrays in Python's memory (numpy arrays, the values of an xarray.DataArray): the
// arrays are read where they lie, through their strides, straight into the series' densities, and go
// through the same assembly as every file reader (value range, missing values, density mapping;
// src/data/readers/series_assembly.h), so a series from arrays equals the series read from the same
// values in a file.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "tstyles/data/cf_conventions.h"
#include "tstyles/data/series.h"

namespace tstyles::python {

// Where the nodes along one axis lie: evenly `spacing` apart from the placement origin, or at the
// given coordinates (world positions, CF attributes read like the NetCDF reader reads them).
struct AxisNodes {
    double spacing = 1.0;
    std::optional<std::vector<double>> coordinates;
    CfAttributes attributes;
    std::string name;  // the coordinate's name, for messages ("lat"); x, y or z for plain arrays
};

// One time-step as the caller gave it. Values are 3D (z, y, x); a mask has the values' shape.
struct ArrayStep {
    pybind11::array values;
    std::optional<pybind11::array> mask;
    double time = 0.0;
    std::array<AxisNodes, 3> axes;  // x, y, z
    glm::dvec3 origin{0.0};         // added to the coordinates' first nodes
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
};

// How stored values become data, as CF packs them: values equal to a marker are missing (compared in
// the array's own precision), the others are value * scale + offset. NaN is always missing.
struct ArrayPacking {
    std::vector<double> missingValues;
    double scale = 1.0;
    double offset = 0.0;
};

struct ArraySeries {
    std::string source;  // names the input in messages: "tstyles.Series", "DataArray 'thetao'"
    std::string format;  // Series::sourceFormat: "numpy array", "xarray DataArray"
    std::string name;
    std::string valueUnit;
    std::optional<std::array<SpatialAxis, 3>> axes;  // none: from the coordinates' CF attributes
    TimeAxis time;
    std::vector<ArrayStep> steps;
    ArrayPacking packing;
    std::optional<std::array<double, 2>> valueRange;
    DensityPrecision precision = DensityPrecision::Bits16;
};

// The series of densities. Problems (shapes, dtypes, times, coordinates, Inf values, a range that
// cannot be derived) are InputErrors naming `source`, the argument and the problem.
Series buildArraySeries(const ArraySeries& input);

}  // namespace tstyles::python
