// Reading a time-step's raw value and mask files, checking them against the grid, and mapping raw
// values to density. Errors name the manifest, the field that named the file and the time-step.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

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
    std::vector<float> values;
    std::array<double, 2> range{0.0, 0.0};  // min, max
};

// Reads dims.x * dims.y * dims.z little-endian values of `type`; the file size must match exactly and
// float32 values must be finite.
RawValues readRawValues(const RawFileSource& source, const glm::ivec3& dims, ValueType type);

// Reads one uint8 per voxel.
std::vector<std::uint8_t> readMask(const RawFileSource& source, const glm::ivec3& dims);

// Maps raw values in place to density: clamp((v - lo) / (hi - lo), 0, 1). Needs lo < hi.
void normalizeToDensity(std::vector<float>& values, const std::array<double, 2>& valueRange);

}  // namespace tstyles
