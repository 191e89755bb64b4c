// What the density atlas holds for a time-step. Without missing values: one 16-bit density per
// voxel. With them: (density * validity, validity) pairs, so that one filtered fetch gives both
// with the same weights and the shader can divide them out (shaders/volume_sampling.glsl). GL-free.
#pragma once

#include <cstdint>
#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

// True when any voxel of any time-step has no data.
bool hasMissingValues(const Series& series);

// One uint16 per voxel, or two (premultiplied density, validity 0 or 65535) with `withValidity`;
// a missing voxel becomes (0, 0).
std::vector<std::uint16_t> densityTexels(const TimeStep& step, bool withValidity);

// The same at a chosen precision, as the bytes of the texture upload: uint8 (0..255), uint16
// (0..65535) or float32 (0..1) per channel, native byte order.
std::vector<std::uint8_t> densityTexelBytes(const TimeStep& step, bool withValidity, DensityPrecision precision);

}  // namespace tstyles
