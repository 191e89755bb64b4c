// What the driver says about the memory textures may take.
#include "tstyles/render/gpu_memory_limits.h"

#include <string>

#include "render_size_limits.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/gl/objects.h"

namespace tstyles {
namespace {

// GL_NVX_gpu_memory_info: video memory free now, in KiB (NVIDIA).
constexpr GLenum kGpuMemoryAvailableNvx = 0x9049;

bool isLlvmpipe() {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return renderer != nullptr && std::string(renderer).find("llvmpipe") != std::string::npos;
}

// What the series' own host copy takes: one float per voxel, one byte per mask voxel.
std::uint64_t hostSeriesBytes(const Series& series) {
    std::uint64_t bytes = 0;
    for (const TimeStep& step : series.steps)
        bytes += step.density.size() * sizeof(float) + (step.mask ? step.mask->size() : 0);
    return bytes;
}

}  // namespace

GpuMemoryLimits queryGpuMemoryLimits(std::optional<std::uint64_t> given, std::uint64_t hostBytesLeft) {
    GpuMemoryLimits limits;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
    limits.maxTextureSize = maxSize;
    if (isLlvmpipe()) limits.largestTextureBytes = kLlvmpipeLargestTexture;
    if (given) {
        limits.budgetBytes = *given;
        return limits;
    }
    GLint freeKib = 0;
    if (hasGlExtension("GL_NVX_gpu_memory_info")) glGetIntegerv(kGpuMemoryAvailableNvx, &freeKib);
    if (freeKib > 0) {
        limits.budgetBytes = std::uint64_t(freeKib) * 1024;
        limits.budgetSource = "the GPU's free memory, GL_NVX_gpu_memory_info";
    } else {
        limits.budgetBytes = hostBytesLeft;
        limits.budgetSource = "host memory: the --max-memory cap less the series' own copy";
    }
    return limits;
}

GpuMemoryLimits gpuMemoryLimitsFor(const Series& series, std::optional<std::uint64_t> given,
                                   std::optional<std::uint64_t> maxHostMemory) {
    const std::uint64_t cap = memoryCap(maxHostMemory);
    const std::uint64_t host = hostSeriesBytes(series);
    return queryGpuMemoryLimits(given, cap > host ? cap - host : 0);
}

}  // namespace tstyles
