// The GPU memory budget option, and the one line that says what it chose.
#include "gpu_memory_option.h"

#include <iostream>

#include <CLI/CLI.hpp>

#include "tstyles/render/gpu_memory_limits.h"

namespace tstyles::cli {
namespace {

constexpr const char* kOption = "--max-gpu-memory";

}  // namespace

void addGpuMemoryOption(CLI::App& command, GpuMemoryOption& option) {
    command.add_option(kOption, option.maxGpuMemory,
                       "GPU memory the series' textures may take, e.g. 512M, 4G; a larger series is stored smaller "
                       "(no packed atlas, fewer bits where no value changes) or coarser, and says so "
                       "(default: the GPU's free memory, or the host's under --max-memory)");
}

std::optional<std::uint64_t> parseGpuMemoryOption(const GpuMemoryOption& option) {
    if (!option.maxGpuMemory) return std::nullopt;
    return parseMemorySize(*option.maxGpuMemory, kOption);
}

GpuResidency uploadWithinGpuMemory(Renderer& renderer, const Series& series, const GpuMemoryOption& option,
                                   const DatasetOptions& dataset, const std::optional<WholeSeries>& whole) {
    const std::optional<std::uint64_t> maxHostMemory = toReadOptions(dataset).maxMemoryBytes;
    const GpuMemoryLimits limits = gpuMemoryLimitsFor(series, parseGpuMemoryOption(option), maxHostMemory);
    const GpuResidency residency = renderer.setSeries(series, limits, whole);
    if (option.maxGpuMemory || residency.changed()) std::cerr << "tstyles: " << residencyText(series, limits, residency) << "\n";
    return residency;
}

void describeGpuMemory(std::ostream& out, const Series& series, const GpuMemoryOption& option) {
    const std::optional<std::uint64_t> budget = parseGpuMemoryOption(option);
    if (!budget) return;
    GpuMemoryLimits limits;
    limits.budgetBytes = *budget;
    out << "\nGPU memory (assuming GL_MAX_3D_TEXTURE_SIZE 2048): " << residencyText(series, limits, fitToGpuMemory(series, limits))
        << "\n";
}

}  // namespace tstyles::cli
