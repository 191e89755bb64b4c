// Which smaller density precision holds a series' values exactly as the precision it asks for,
// so that a GPU memory budget can store it smaller without changing a value. GL-free.
#pragma once

#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

// Whether every density of the series reads back from `smaller` storage as it does from
// `requested` storage: at 8 bits where the 16-bit texel of every value is a multiple of 257 (k/255
// = 257k/65535), at 8 or 16 bits for 32 where the quantised value is within 1e-6 of the float (a
// sixtieth of a 16-bit step, below anything a 1024-entry transfer function tells apart). Missing
// values and masks are 0 or full scale at every precision and do not count.
bool holdsExactly(const Series& series, DensityPrecision requested, DensityPrecision smaller);

// The precisions below `requested` that hold the series exactly, largest first (llvmpipe filters
// 8-bit textures in 8-bit arithmetic: docs/large-series.md).
std::vector<DensityPrecision> losslessSmallerPrecisions(const Series& series, DensityPrecision requested);

}  // namespace tstyles
