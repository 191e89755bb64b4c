// Reading a time-step's raw value and mask files, checking them against the grid, and mapping raw
// values to density. Errors name the manifest, the field that named the file and the time-step.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/data/node_block.h"
#include "tstyles/data/series.h"

namespace tstyles {

// Where a raw file was named, so that a problem with its contents can point back at the manifest.
struct RawFileSource {
    std::filesystem::path manifest;
    std::string field;  // e.g. "time_steps[3].values.file"
    std::size_t stepIndex = 0;
    std::filesystem::path file;  // resolved against the manifest's folder
};

struct RawValues {
    // The raw values, x fastest; float holds every uint8, uint16 and float32 value exactly.
    // Missing values are missingDensity() (NaN).
    std::vector<float> values;
    // Min and max over the values that are not missing; NaN, NaN when every value is missing.
    std::array<double, 2> range{0.0, 0.0};
};

// How much of a value file a reader that keeps one block reads.
enum class BlockReach {
    WholeFile,  // read through: the range and the checks cover every value of the file
    BlockRows,  // only the block's rows: the range and the checks cover the block's values
};

// Reads dims.x * dims.y * dims.z little-endian values of `type`; the file size must match exactly.
// A value equal to `missingMarker` is missing, and so is NaN in float data; an infinity is an
// error. With `kept`, only that block's values are kept (x fastest
// within it), and memory holds the block alone; `reach` says whether the whole file is still read
// past in chunks, so that the range and the checks cover every value as without `kept`, or only
// the block's rows are read.
RawValues readRawValues(const RawFileSource& source, const glm::ivec3& dims, ValueType type,
                        std::optional<double> missingMarker, const std::optional<NodeBlock>& kept = std::nullopt,
                        BlockReach reach = BlockReach::WholeFile);

// Reads one uint8 per voxel; with `kept`, only that block's rows.
std::vector<std::uint8_t> readMask(const RawFileSource& source, const glm::ivec3& dims,
                                   const std::optional<NodeBlock>& kept = std::nullopt);

// Reads a whole file of exactly `expectedBytes` bytes (`kind` and `layout` word the size error:
// "coordinates file", "17 x 9 x 5 nodes, 3 float32 each").
std::vector<std::uint8_t> readExactBytes(const RawFileSource& source, const std::string& kind,
                                         std::size_t expectedBytes, const std::string& layout);

// Maps raw values in place to density: clamp((v - lo) / (hi - lo), 0, 1). Needs lo < hi. Missing
// values stay missing.
void normalizeToDensity(std::vector<float>& values, const std::array<double, 2>& valueRange);

}  // namespace tstyles
