// `tstyles bench --distributed` under mpirun: the bundled datasets rendered sort-last by every
// process of the run (DistributedRendering), each frame split into rendering (the slowest
// process's block) and compositing, for the strong-scaling figures of docs/scaling.md.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "commands.h"
#include "gpu_memory_option.h"

namespace tstyles::cli {

struct DistributedBenchOptions {
    std::vector<std::string> datasets;
    std::vector<glm::ivec2> sizes;
    int frames = 7;
    int warmup = 2;
    std::optional<std::filesystem::path> json;
    GpuMemoryOption gpuMemory;  // each process's block within it
    GlOptions gl;
};

int runDistributedBench(const DistributedBenchOptions& options);

}  // namespace tstyles::cli
