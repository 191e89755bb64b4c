// What a reader finds in a file before any values are read: the time-steps' grids, placements and
// value types, and a way to read one time-step's values. The assembly (series_assembly.h) then
// selects steps, checks memory, resamples and maps values to density the same way for every format.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

struct SourceStep {
    double time = 0.0;
    Grid grid;  // rectilinear for most formats; structured for Plot3D
    Placement placement;
    ValueType type = ValueType::Float32;
    std::filesystem::path file;  // the file the values come from
};

struct SourceSeries {
    std::string name;
    std::filesystem::path file;  // what the user named (the first file of a list)
    std::string format;          // "NetCDF", "NIfTI-1", "NRRD", ... for messages and `info`
    std::vector<SourceStep> steps;
    // What world x, y and z mean, as far as the file says (Series::axes).
    std::array<SpatialAxis, 3> axes;
    TimeAxis time;  // Series::time
    std::string valueUnit;  // Series::valueUnit
    std::vector<std::string> notes;  // Series::readingNotes: how it was read, where the file left a choice
    // The raw values of a time-step, x fastest, after the file's scale and offset; declared missing
    // values are missingDensity() (NaN). Undeclared NaN or Inf is an InputError naming the file.
    std::function<std::vector<float>(std::size_t step)> readStep;
};

}  // namespace tstyles
