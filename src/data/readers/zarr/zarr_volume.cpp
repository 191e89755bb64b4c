// Walks the chunks that a volume crosses and copies their part of it, in C or Fortran order.
#include "zarr_volume.h"

#include <algorithm>

#include "zarr_chunk_reader.h"

namespace tstyles {
namespace {

// Where element (i0, i1, ...) of a chunk sits among its values.
std::vector<std::size_t> chunkStrides(const ZarrArray& array) {
    const std::size_t dimensions = array.chunkShape.size();
    std::vector<std::size_t> strides(dimensions, 1);
    for (std::size_t step = 1; step < dimensions; ++step) {
        const std::size_t axis = array.fortranOrder ? step : dimensions - 1 - step;
        const std::size_t inner = array.fortranOrder ? axis - 1 : axis + 1;
        strides[axis] = strides[inner] * std::size_t(array.chunkShape[inner]);
    }
    return strides;
}

struct VolumeFrame {
    std::array<std::uint64_t, 3> dims{};  // x, y, z samples
    std::array<std::uint64_t, 3> chunk{};  // x, y, z chunk sizes
};

// Copies the part of one chunk (nullopt: its fill value) that lies in the volume.
void copyChunk(const ZarrArray& array, const ZarrVolumeSlice& slice, const VolumeFrame& frame,
               const std::array<std::uint64_t, 3>& chunkAt, const std::optional<std::vector<std::uint8_t>>& bytes,
               const std::vector<std::size_t>& strides, std::vector<float>& volume) {
    std::vector<float> values;
    if (bytes) values = decodeValues(bytes->data(), array.chunkValues(), array.type, array.byteOrder);
    std::size_t base = 0;
    for (std::size_t axis = 0; axis < array.shape.size(); ++axis)
        if (std::find(slice.spaceDimensions.begin(), slice.spaceDimensions.end(), axis) == slice.spaceDimensions.end())
            base += std::size_t(slice.fixedIndex[axis] % array.chunkShape[axis]) * strides[axis];
    std::array<std::uint64_t, 3> start{}, end{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
        start[axis] = chunkAt[axis] * frame.chunk[axis];
        end[axis] = std::min(frame.dims[axis], start[axis] + frame.chunk[axis]);
    }
    const std::size_t sx = strides[slice.spaceDimensions[0]];
    const std::size_t sy = strides[slice.spaceDimensions[1]];
    const std::size_t sz = strides[slice.spaceDimensions[2]];
    const float fill = float(array.fillValue);
    for (std::uint64_t z = start[2]; z < end[2]; ++z)
        for (std::uint64_t y = start[1]; y < end[1]; ++y) {
            float* row = volume.data() + std::size_t((z * frame.dims[1] + y) * frame.dims[0]);
            const std::size_t local = base + std::size_t(z - start[2]) * sz + std::size_t(y - start[1]) * sy;
            for (std::uint64_t x = start[0]; x < end[0]; ++x)
                row[x] = bytes ? values[local + std::size_t(x - start[0]) * sx] : fill;
        }
}

}  // namespace

std::vector<float> readZarrVolume(const ZarrArray& array, const ZarrVolumeSlice& slice) {
    VolumeFrame frame;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        frame.dims[axis] = array.shape[slice.spaceDimensions[axis]];
        frame.chunk[axis] = array.chunkShape[slice.spaceDimensions[axis]];
    }
    std::vector<float> volume(std::size_t(frame.dims[0] * frame.dims[1] * frame.dims[2]));
    const std::vector<std::size_t> strides = chunkStrides(array);
    std::vector<std::uint64_t> chunkIndex(array.shape.size());
    for (std::size_t axis = 0; axis < array.shape.size(); ++axis) chunkIndex[axis] = slice.fixedIndex[axis] / array.chunkShape[axis];
    std::array<std::uint64_t, 3> counts{};
    for (std::size_t axis = 0; axis < 3; ++axis) counts[axis] = (frame.dims[axis] + frame.chunk[axis] - 1) / frame.chunk[axis];
    ZarrShardIndexes shardIndexes;
    std::array<std::uint64_t, 3> at{};
    for (at[2] = 0; at[2] < counts[2]; ++at[2])
        for (at[1] = 0; at[1] < counts[1]; ++at[1])
            for (at[0] = 0; at[0] < counts[0]; ++at[0]) {
                for (std::size_t axis = 0; axis < 3; ++axis) chunkIndex[slice.spaceDimensions[axis]] = at[axis];
                copyChunk(array, slice, frame, at, readZarrChunk(array, chunkIndex, shardIndexes), strides, volume);
            }
    return volume;
}

}  // namespace tstyles
