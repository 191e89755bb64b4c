// Reading and writing a series as a JSON manifest plus raw value files (format: docs/dataset-format.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>

#include "tstyles/data/node_block.h"
#include "tstyles/data/series.h"

namespace tstyles {

// What a series may take: memory (none given: half of the machine's, defaultMemoryCap()) for 4
// bytes a voxel in memory, a mask byte where there is a mask, and the GPU's copy.
// Where a process keeps one block of every time-step (distributed rendering): `nodesToRead` says,
// before a time-step's files are opened, which of its nodes to keep (none: all). Where the
// manifest gives "value_range", only the block's rows of each value file are read, and rawRange
// and the checks of the values (NaN, Inf) cover the block; the process whose block holds a bad
// value finds it. Otherwise the files are still read through in chunks, so rawRange and the
// checks cover the whole file and every process finds the whole series' range; memory holds the
// block alone either way. Then
// `afterStepRead` is called with the time-step as read (values cut, grid still whole; missing
// values NaN), before the values are mapped to density, to cut its grid alike.
using StepNodesToRead = std::function<std::optional<NodeBlock>(std::size_t index, const TimeStep& outline)>;
using StepReadHook = std::function<void(std::size_t index, TimeStep& step)>;

struct ManifestLimits {
    std::optional<std::uint64_t> maxMemoryBytes;  // --max-memory
    std::size_t gpuBytesPerVoxel = 2;             // --precision 16
    // With them, the memory check counts `keptVoxels`, the voxels kept of all time-steps, rather
    // than the whole series.
    StepNodesToRead nodesToRead;
    StepReadHook afterStepRead;
    std::size_t keptVoxels = 0;
};

// Loads the manifest and every value and mask file it names (paths relative to the manifest).
// Any problem is an InputError naming the file, the field and what is wrong; a series over the
// memory limit is refused, with the figure it needs, before any value file is read. A dataset
// folder may be given instead of its manifest: it stands for the folder's series.json.
Series loadSeries(const std::filesystem::path& manifestPath, const ManifestLimits& limits = {});

// The manifest's series without its values: times, grids, placements, axes and metadata, checked
// as loadSeries checks them, with no value or mask file opened. valueRange is the manifest's
// "value_range", or NaN, NaN where the range comes from the data.
Series loadSeriesOutline(const std::filesystem::path& manifestPath);

// One time-step's values as they should be written to disk.
struct RawTimeStep {
    double time = 0.0;
    RectilinearGrid grid;  // uneven axes (axisPositions) are written as grid.positions
    // When set, the time-step is on this structured grid instead (its dims count the values);
    // time-steps sharing one node array share one coordinates file.
    std::optional<StructuredGrid> structured;
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
    // The raw value that marks a voxel without data (NaN: NaN values in float32 files); none: every
    // value is data.
    std::optional<double> missingValue;
    std::vector<RawTimeStep> steps;
    std::array<SpatialAxis, 3> axes;  // written when any is known
    TimeAxis time;                    // written when it has a unit
};

// Writes `directory`/series.json and one raw file per time-step (and mask). Every file goes
// through a temporary name and a rename, so a failed write leaves nothing half-written.
void writeSeries(const RawSeries& series, const std::filesystem::path& directory);

}  // namespace tstyles
