// The interactive viewer's entry point, as `tstyles view` calls it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/read_options.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"

namespace tstyles::viewer {

struct ViewerOptions {
    // A scene file or a dataset (a manifest or its folder, or a file docs/readers.md lists); several:
    // the files of one series; none: the bundled default.
    std::vector<std::filesystem::path> inputs;
    // How the first dataset is read (--var, --steps, ...); files opened later use the defaults.
    ReadOptions readOptions;
    // --max-gpu-memory: what every series the viewer shows may take on the GPU (default: the GPU's
    // free memory, or the host's under --max-memory; docs/large-series.md).
    std::optional<std::uint64_t> maxGpuMemoryBytes;
    std::filesystem::path dataDirectory;  // where the bundled default is looked for
    std::optional<std::filesystem::path> script;
    glm::ivec2 windowSize{1280, 800};
    std::optional<std::filesystem::path> shaderDirectory;
    bool vsync = true;
    // Applied to the first scene once it is fitted to its series (`view --ray`); `automaticScene`
    // where the inputs were a dataset. May throw InputError.
    std::function<void(Scene& scene, const Series& series, bool automaticScene)> adjustFirstScene;
};

// Opens the window and runs until it is closed or a script quits. Returns the exit code (0).
// Throws InputError for a bad input or script and GlUnavailableError when no window with OpenGL
// 4.5 can be opened.
int runViewer(const ViewerOptions& options);

}  // namespace tstyles::viewer
