// What the density atlas holds for a time-step. Without missing values: one 16-bit density per
// voxel. With them: (density * validity, validity) pairs, so that one filtered fetch gives both
// with the same weights and the shader can divide them out (shaders/volume_sampling.glsl). A series
// with segmentation masks adds the mask as the last channel, so the same fetch gives it too.
// GL-free.
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

// The channels of a density atlas texel: density (premultiplied by validity with missing values),
// validity with missing values, and the mask in series with masks.
int densityChannelCount(bool withValidity, bool withMask);

// The same at a chosen precision, as the bytes of the texture upload: uint8 (0..255), uint16
// (0..65535) or float32 (0..1) per channel, native byte order. With `withMask` a last channel holds
// the step's mask, full scale inside (and everywhere for a step without a mask) and 0 outside.
std::vector<std::uint8_t> densityTexelBytes(const TimeStep& step, bool withValidity, bool withMask,
                                            DensityPrecision precision);

}  // namespace tstyles
