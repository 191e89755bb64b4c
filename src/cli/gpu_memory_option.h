// --max-gpu-memory SIZE: the GPU memory budget of render, animate, view, bench and info
// (docs/large-series.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "cli11_forward.h"

#include "commands.h"
#include "tstyles/render/renderer.h"

namespace tstyles::cli {

struct GpuMemoryOption {
    std::optional<std::string> maxGpuMemory;  // as typed
};
void addGpuMemoryOption(CLI::App& command, GpuMemoryOption& option);

// The budget in bytes; an InputError naming --max-gpu-memory for a bad size. Call before reading
// the dataset, so that a typo costs nothing.
std::optional<std::uint64_t> parseGpuMemoryOption(const GpuMemoryOption& option);

// Uploads the series within the budget (--max-gpu-memory, else the driver's or the host's, see
// queryGpuMemoryLimits) and says on stderr what was chosen where a budget was given or anything
// had to change. `whole`: where `series` is one process's block (Renderer::setSeries).
// Returns what was chosen.
GpuResidency uploadWithinGpuMemory(Renderer& renderer, const Series& series, const GpuMemoryOption& option,
                                   const DatasetOptions& dataset, const std::optional<WholeSeries>& whole = std::nullopt);

// `info`: what render would choose within --max-gpu-memory, assuming GL_MAX_3D_TEXTURE_SIZE 2048;
// nothing without the option.
void describeGpuMemory(std::ostream& out, const Series& series, const GpuMemoryOption& option);

}  // namespace tstyles::cli
