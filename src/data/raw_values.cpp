// Raw little-endian value files: size checks, decoding, finiteness, and the mapping to density.
#include "raw_values.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <fstream>
#include <limits>
#include <system_error>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

std::string dimsText(const glm::ivec3& dims) {
    return std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " + std::to_string(dims.z);
}

[[noreturn]] void failFile(const RawFileSource& source, const std::string& kind, const std::string& problem) {
    throwInputError(source.manifest, source.field,
                    kind + " '" + source.file.string() + "' of time-step " +
                        std::to_string(source.stepIndex) + " " + problem);
}

// Reads the whole file after checking that it exists and has exactly `expectedBytes`, so a wrong
// grid or type is reported as a size mismatch rather than as garbage values.
std::vector<std::uint8_t> readExactly(const RawFileSource& source, const std::string& kind,
                                      std::size_t expectedBytes, const std::string& layout) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(source.file, error)) failFile(source, kind, "not found");
    const std::uintmax_t actualBytes = std::filesystem::file_size(source.file, error);
    if (error) failFile(source, kind, "cannot be read: " + error.message());
    if (actualBytes != expectedBytes) {
        const char* verdict = actualBytes < expectedBytes ? "is truncated" : "is too large";
        failFile(source, kind,
                 std::string(verdict) + ": expected " + std::to_string(expectedBytes) + " bytes (" + layout +
                     "), found " + std::to_string(actualBytes) + " bytes");
    }
    std::vector<std::uint8_t> bytes(expectedBytes);
    std::ifstream in(source.file, std::ios::binary);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!in || static_cast<std::size_t>(in.gcount()) != bytes.size()) {
        failFile(source, kind, "cannot be read");
    }
    return bytes;
}

// Decoding byte by byte keeps the files little-endian whatever the host's byte order.
float decodeValue(const std::uint8_t* bytes, ValueType type) {
    switch (type) {
        case ValueType::UInt8:
            return float(bytes[0]);
        case ValueType::UInt16:
            return float(std::uint16_t(bytes[0] | (bytes[1] << 8)));
        case ValueType::Float32: {
            const std::uint32_t bits = std::uint32_t(bytes[0]) | (std::uint32_t(bytes[1]) << 8) |
                                       (std::uint32_t(bytes[2]) << 16) | (std::uint32_t(bytes[3]) << 24);
            return std::bit_cast<float>(bits);
        }
    }
    return 0.0f;
}

std::string voxelText(std::size_t index, const glm::ivec3& dims) {
    const std::size_t nx = std::size_t(dims.x);
    const std::size_t ny = std::size_t(dims.y);
    return std::string("(") + std::to_string(index % nx) + ", " + std::to_string((index / nx) % ny) + ", " +
           std::to_string(index / (nx * ny)) + ")";
}

}  // namespace

RawValues readRawValues(const RawFileSource& source, const glm::ivec3& dims, ValueType type) {
    const std::size_t stride = bytesPerValue(type);
    const std::size_t count = std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
    const std::vector<std::uint8_t> bytes =
        readExactly(source, "value file", count * stride, dimsText(dims) + " " + toString(type) + " values");

    RawValues raw;
    raw.values.resize(count);
    float lowest = std::numeric_limits<float>::infinity();
    float highest = -std::numeric_limits<float>::infinity();
    for (std::size_t index = 0; index < count; ++index) {
        const float value = decodeValue(bytes.data() + index * stride, type);
        if (!std::isfinite(value)) {
            failFile(source, "value file",
                     std::string("holds a non-finite value (") + (std::isnan(value) ? "NaN" : "Inf") +
                         ") at voxel (x, y, z) = " + voxelText(index, dims));
        }
        raw.values[index] = value;
        lowest = std::min(lowest, value);
        highest = std::max(highest, value);
    }
    raw.range = {double(lowest), double(highest)};
    return raw;
}

std::vector<std::uint8_t> readMask(const RawFileSource& source, const glm::ivec3& dims) {
    return readExactly(source, "mask file", std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z),
                       dimsText(dims) + " uint8 values");
}

void normalizeToDensity(std::vector<float>& values, const std::array<double, 2>& valueRange) {
    const double low = valueRange[0];
    const double width = valueRange[1] - valueRange[0];
    for (float& value : values) {
        value = float(std::clamp((double(value) - low) / width, 0.0, 1.0));
    }
}

}  // namespace tstyles
