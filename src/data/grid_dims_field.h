// A grid's "dims" in a manifest or a grid file: three sample counts read as one field, with the
// wording of the grid kind's errors.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "tstyles/core/json_field.h"

namespace tstyles {

// The most samples one time-step's grid may have (2^36): beyond any GPU's memory, and far from overflow.
inline constexpr std::uint64_t kMaxVoxelsPerStep = std::uint64_t(1) << 36;

// How a grid kind words the errors of its "dims" (the messages name what is counted).
struct GridDimsWording {
    const char* expectedThree;  // e.g. "expected 3 sample counts (x, y, z)"
    const char* whyTwo;         // why each count must be at least 2
    const char* tooMany;        // e.g. "too many voxels for one time-step"
};

// A grid's "dims": three integers, each at least 2, whose product is at most `maxCount`.
glm::ivec3 readGridDims(const JsonField& dims, std::uint64_t maxCount, const GridDimsWording& wording);

}  // namespace tstyles
