// The GPU memory a series may take on the current context's driver. Needs a current context.
#pragma once

#include <cstdint>
#include <optional>

#include "tstyles/render/gpu_memory_budget.h"

namespace tstyles {

// Mesa's llvmpipe refuses a texture over 2 GiB (LP_MAX_TEXTURE_SIZE: 32-bit signed offsets) with
// GL_OUT_OF_MEMORY; measured: a 1024 x 1024 x 512 R32F atlas (2 GiB) uploads, 1024 x 1024 x 576 does not.
inline constexpr std::uint64_t kLlvmpipeLargestTexture = std::uint64_t(2) << 30;

// The budget is `given` (--max-gpu-memory), else the free video memory the driver reports
// (GL_NVX_gpu_memory_info), else `hostBytesLeft`: llvmpipe and OSMesa keep textures in host
// memory, under the same cap as the series' own copy. Adds llvmpipe's largest texture and
// GL_MAX_3D_TEXTURE_SIZE.
GpuMemoryLimits queryGpuMemoryLimits(std::optional<std::uint64_t> given, std::uint64_t hostBytesLeft);

// queryGpuMemoryLimits for `series` as every front end (render, animate, view, bench) uploads it:
// `given` is --max-gpu-memory, `maxHostMemory` --max-memory (default: memoryCap's), of which the
// series' own host copy (a float per voxel, a byte per mask voxel) is already taken.
GpuMemoryLimits gpuMemoryLimitsFor(const Series& series, std::optional<std::uint64_t> given,
                                   std::optional<std::uint64_t> maxHostMemory);

}  // namespace tstyles
