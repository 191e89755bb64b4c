// Reading and writing a series as a JSON manifest plus raw value files (format: docs/dataset-format.md).
#pragma once

#include <filesystem>

#include "tstyles/data/series.h"

namespace tstyles {

// Loads the manifest and every value and mask file it names (paths relative to the manifest).
// Any problem is an InputError naming the file, the field and what is wrong. A dataset folder may be
// given instead of its manifest: it stands for the folder's series.json.
Series loadSeries(const std::filesystem::path& manifestPath);

// One time-step's values as they should be written to disk.
struct RawTimeStep {
    double time = 0.0;
    RectilinearGrid grid;
    // When set, the time-step lies on this beam (sonar) grid instead, and `grid` is not written.
    std::optional<BeamGrid> beamGrid;
    Placement placement;
    ValueType type = ValueType::Float32;
    std::vector<std::uint8_t> bytes;                  // little-endian values, x fastest
    std::optional<std::vector<std::uint8_t>> mask;    // same dims, or none
};

struct RawSeries {
    std::string name;
    std::array<double, 2> valueRange{0.0, 1.0};
    std::vector<RawTimeStep> steps;
};

// Writes `directory`/series.json and one raw file per time-step (and mask). Every file goes
// through a temporary name and a rename, so a failed write leaves nothing half-written.
void writeSeries(const RawSeries& series, const std::filesystem::path& directory);

}  // namespace tstyles
