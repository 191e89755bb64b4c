// One 3D volume out of an N-dimensional Zarr array: the dimensions that are x, y and z, every other
// dimension held at one index (a time-step, a channel), read chunk by chunk into x-fastest floats.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "zarr_array.h"

namespace tstyles {

struct ZarrVolumeSlice {
    std::array<std::size_t, 3> spaceDimensions{};  // the array dimension of x, y and z
    std::vector<std::uint64_t> fixedIndex;         // per array dimension; unused for x, y, z
};

// The values, x fastest; chunks not stored are the fill value (NaN for a NaN fill value).
std::vector<float> readZarrVolume(const ZarrArray& array, const ZarrVolumeSlice& slice);

}  // namespace tstyles
