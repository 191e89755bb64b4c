// Raw little-endian value files: size checks, decoding, finiteness, and the mapping to density.
#include "raw_values.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <fstream>
#include <limits>
#include <system_error>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/user_paths.h"
#include "value_decoding.h"

namespace tstyles {
namespace {

std::string valueLayoutText(const glm::ivec3& dims) {
    return std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " + std::to_string(dims.z);
}

[[noreturn]] void failFile(const RawFileSource& source, const std::string& kind, const std::string& problem) {
    throwInputError(source.manifest, source.field,
                    kind + " '" + source.file.string() + "' of time-step " +
                        std::to_string(source.stepIndex) + " " + problem);
}

// Values decoded per read: the file's bytes never sit in memory beside all of its values, so a
// time-step takes its float values' memory and no more (a 4 GiB float32 file took 8 GiB).
constexpr std::size_t kValuesPerRead = std::size_t(1) << 20;

// Opens the file after checking that it exists and has exactly `expectedBytes`, so a wrong grid or
// type is reported as a size mismatch rather than as garbage values.
std::ifstream openExactly(const RawFileSource& source, const std::string& kind, std::size_t expectedBytes,
                          const std::string& layout) {
    if (userPathKind({source.manifest, source.field}, source.file) == PathKind::Missing) failFile(source, kind, "not found");
    std::error_code error;
    if (!std::filesystem::is_regular_file(source.file, error))
        failFile(source, kind, "is not a regular file (a folder, device or FIFO cannot be read as data)");
    const std::uintmax_t actualBytes = std::filesystem::file_size(source.file, error);
    if (error) failFile(source, kind, "cannot be read: " + error.message());
    if (actualBytes != expectedBytes) {
        const char* verdict = actualBytes < expectedBytes ? "is truncated" : "is too large";
        failFile(source, kind,
                 std::string(verdict) + ": expected " + std::to_string(expectedBytes) + " bytes (" + layout +
                     "), found " + std::to_string(actualBytes) + " bytes");
    }
    std::ifstream in(source.file, std::ios::binary);
    if (!in) failFile(source, kind, "cannot be opened for reading");
    return in;
}

void readInto(std::ifstream& in, const RawFileSource& source, const std::string& kind, std::uint8_t* bytes,
              std::size_t count) {
    in.read(reinterpret_cast<char*>(bytes), static_cast<std::streamsize>(count));
    if (!in || static_cast<std::size_t>(in.gcount()) != count) failFile(source, kind, "cannot be read");
}

// The whole file, `expectedBytes` long (openExactly's checks).
std::vector<std::uint8_t> readExactly(const RawFileSource& source, const std::string& kind,
                                      std::size_t expectedBytes, const std::string& layout) {
    std::ifstream in = openExactly(source, kind, expectedBytes, layout);
    // The manifest's series is checked against the cap before its files are read; this is the
    // backstop for files read before that (a structured grid's coordinates).
    requireMemory(source.manifest, source.field, double(expectedBytes), defaultMemoryCap(),
                  kind + " '" + source.file.string() + "' (" + layout + ") would");
    std::vector<std::uint8_t> bytes(expectedBytes);
    readInto(in, source, kind, bytes.data(), bytes.size());
    return bytes;
}

std::string voxelText(std::size_t index, const glm::ivec3& dims) {
    const std::size_t nx = std::size_t(dims.x);
    const std::size_t ny = std::size_t(dims.y);
    return std::string("(") + std::to_string(index % nx) + ", " + std::to_string((index / nx) % ny) + ", " +
           std::to_string(index / (nx * ny)) + ")";
}

// Decodes raw values one at a time into a kept list, marking missing ones (the marker, NaN) and
// refusing infinities, and keeps the range of those with data.
class ValueDecoder {
public:
    ValueDecoder(const RawFileSource& source, const glm::ivec3& dims, ValueType type,
                 std::optional<double> missingMarker)
        : source_(source), dims_(dims), type_(type) {
        // Compared in the file's own precision: a float32 file stores the marker 1e35 as float(1e35).
        // NaN is missing whether or not the manifest declares it (a "NaN" marker only says so).
        markerIsSet_ = missingMarker && !std::isnan(*missingMarker);
        marker_ = markerIsSet_ ? float(*missingMarker) : 0.0f;
    }

    // The value at `bytes`, the file's value number `index`; appended to `values` where `keep`.
    void decode(const std::uint8_t* bytes, std::size_t index, bool keep, std::vector<float>& values, std::size_t& next) {
        const float value = float(decodeValue(bytes, type_, ByteOrder::Little));
        if ((markerIsSet_ && value == marker_) || std::isnan(value)) {
            if (keep) values[next++] = missingDensity();
            return;
        }
        if (std::isinf(value)) {
            failFile(source_, "value file",
                     std::string("holds a non-finite value (") + (value > 0 ? "Inf" : "-Inf") +
                         ") at voxel (x, y, z) = " + voxelText(index, dims_) +
                         ": only NaN (or the declared missing_value) marks missing data");
        }
        if (keep) values[next++] = value;
        lowest_ = std::min(lowest_, value);
        highest_ = std::max(highest_, value);
    }

    std::array<double, 2> range() const {
        const double none = std::numeric_limits<double>::quiet_NaN();
        return lowest_ <= highest_ ? std::array<double, 2>{double(lowest_), double(highest_)}
                                   : std::array<double, 2>{none, none};
    }

private:
    const RawFileSource& source_;
    glm::ivec3 dims_;
    ValueType type_;
    bool markerIsSet_ = false;
    float marker_ = 0.0f;
    float lowest_ = std::numeric_limits<float>::infinity();
    float highest_ = -std::numeric_limits<float>::infinity();
};

}  // namespace

RawValues readRawValues(const RawFileSource& source, const glm::ivec3& dims, ValueType type,
                        std::optional<double> missingMarker, const std::optional<NodeBlock>& kept, BlockReach reach) {
    const std::size_t stride = bytesPerValue(type);
    const std::size_t count = std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
    std::ifstream in =
        openExactly(source, "value file", count * stride, valueLayoutText(dims) + " " + toString(type) + " values");
    ValueDecoder decoder(source, dims, type, missingMarker);
    RawValues raw;
    raw.values.resize(kept ? kept->nodeCount() : count);
    std::size_t keptIndex = 0;  // where the next kept value goes

    if (kept && reach == BlockReach::BlockRows) {
        std::vector<std::uint8_t> row(std::size_t(kept->count.x) * stride);
        for (int z = kept->first.z; z < kept->first.z + kept->count.z; ++z)
            for (int y = kept->first.y; y < kept->first.y + kept->count.y; ++y) {
                const std::size_t first =
                    (std::size_t(z) * std::size_t(dims.y) + std::size_t(y)) * std::size_t(dims.x) + std::size_t(kept->first.x);
                in.seekg(std::streamoff(first * stride));
                readInto(in, source, "value file", row.data(), row.size());
                for (int x = 0; x < kept->count.x; ++x)
                    decoder.decode(row.data() + std::size_t(x) * stride, first + std::size_t(x), true, raw.values, keptIndex);
            }
        raw.range = decoder.range();
        return raw;
    }

    glm::ivec3 node(0);  // of `index`, x fastest
    std::vector<std::uint8_t> bytes(std::min(count, kValuesPerRead) * stride);
    for (std::size_t first = 0; first < count; first += kValuesPerRead) {
        const std::size_t values = std::min(kValuesPerRead, count - first);
        readInto(in, source, "value file", bytes.data(), values * stride);
        for (std::size_t offset = 0; offset < values; ++offset) {
            const bool keep = !kept || kept->contains(node);
            if (++node.x == dims.x) {
                node.x = 0;
                if (++node.y == dims.y) {
                    node.y = 0;
                    ++node.z;
                }
            }
            decoder.decode(bytes.data() + offset * stride, first + offset, keep, raw.values, keptIndex);
        }
    }
    raw.range = decoder.range();
    return raw;
}

std::vector<std::uint8_t> readMask(const RawFileSource& source, const glm::ivec3& dims,
                                   const std::optional<NodeBlock>& kept) {
    const std::size_t bytes = std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
    const std::string layout = valueLayoutText(dims) + " uint8 values";
    if (!kept) return readExactly(source, "mask file", bytes, layout);
    std::ifstream in = openExactly(source, "mask file", bytes, layout);
    std::vector<std::uint8_t> mask(kept->nodeCount());
    std::uint8_t* row = mask.data();
    for (int z = kept->first.z; z < kept->first.z + kept->count.z; ++z)
        for (int y = kept->first.y; y < kept->first.y + kept->count.y; ++y, row += kept->count.x) {
            const std::size_t rowStart = (std::size_t(z) * std::size_t(dims.y) + std::size_t(y)) * std::size_t(dims.x);
            in.seekg(std::streamoff(rowStart + std::size_t(kept->first.x)));
            readInto(in, source, "mask file", row, std::size_t(kept->count.x));
        }
    return mask;
}

std::vector<std::uint8_t> readExactBytes(const RawFileSource& source, const std::string& kind,
                                         std::size_t expectedBytes, const std::string& layout) {
    return readExactly(source, kind, expectedBytes, layout);
}

void normalizeToDensity(std::vector<float>& values, const std::array<double, 2>& valueRange) {
    const double low = valueRange[0];
    const double width = valueRange[1] - valueRange[0];
    for (float& value : values) {
        if (isMissing(value)) continue;
        value = float(std::clamp((double(value) - low) / width, 0.0, 1.0));
    }
}

}  // namespace tstyles
