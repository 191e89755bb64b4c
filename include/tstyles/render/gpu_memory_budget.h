// Fitting a series into a GPU memory budget: first what leaves the picture as it is (no packed
// atlas, a smaller precision that holds every value), then a coarser resolution for the whole
// series. Sized by the same texture plan GpuSeries allocates from (series_texture_plan.h). GL-free.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/data/series.h"
#include "tstyles/render/series_texture_plan.h"

namespace tstyles {

struct GpuMemoryLimits {
    std::uint64_t budgetBytes = 0;
    // Where the budget came from, for the message: "--max-gpu-memory", "the GPU's free memory", ...
    std::string budgetSource = "--max-gpu-memory";
    // The driver's largest texture in bytes where it has one below the budget (llvmpipe: 2 GiB).
    std::optional<std::uint64_t> largestTextureBytes;
    int maxTextureSize = 2048;  // GL_MAX_3D_TEXTURE_SIZE
};

// What the series becomes on the GPU.
struct GpuResidency {
    SeriesStorage requested;             // as read: its precision, with the packed atlas
    SeriesStorage storage;               // as chosen
    double scale = 1.0;                  // coarser by this much along each axis (1: full resolution)
    std::optional<std::size_t> fullBytes;  // as requested at full size; none: not even one 3D texture
    std::size_t chosenBytes = 0;         // at most; a coarser series may lose its missing values
    glm::ivec3 fullDims{0};              // of the largest time-step
    glm::ivec3 chosenDims{0};

    bool changed() const { return scale != 1.0 || !(storage == requested); }
};

// The first of these that fits the limits: as requested; without the packed atlas; at each
// smaller precision that holds every value (lossless_precision.h), with then without the packed
// atlas; then the finest coarser resolution (2 % steps) at the requested precision. Throws
// InputError naming the series and --max-gpu-memory when nothing fits (a grid that cannot be
// resampled, or not even 2 x 2 x 2 samples per time-step).
GpuResidency fitToGpuMemory(const Series& series, const GpuMemoryLimits& limits);

// What was given up, one phrase each ("no packed atlas (same image, slower)", "8-bit densities
// (every value is stored exactly)", "resolution 1/1.6 per axis (...)"); empty when nothing changed.
std::vector<std::string> residencyChanges(const Series& series, const GpuResidency& residency);

// One line: the file, the budget, the bytes at full size and what was chosen.
std::string residencyText(const Series& series, const GpuMemoryLimits& limits, const GpuResidency& residency);

}  // namespace tstyles
