// `tstyles view [SCENE|DATASET]`: the interactive viewer (a GLFW window with ImGui panels).
#include <memory>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "image_size_text.h"
#include "gpu_memory_option.h"
#include "scene_source.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/format_listing.h"
#include "viewer/viewer.h"

namespace tstyles::cli {
namespace {

struct ViewOptions {
    std::vector<std::filesystem::path> inputs;
    DatasetOptions dataset;
    GpuMemoryOption gpuMemory;
    std::optional<std::filesystem::path> script;
    std::string size = "1280x800";
    bool noVsync = false;
    std::optional<std::filesystem::path> shaderDirectory;
    SceneOverrides overrides;  // --ray and --ray-KEY only
};

glm::ivec2 parseWindowSize(const std::string& text) {
    const std::optional<glm::ivec2> size = parseWidthByHeight(text);
    if (!size) throwInputError("", "--size", "expected WIDTHxHEIGHT such as 1280x800, got \"" + text + "\"");
    if (size->x < 320 || size->y < 240 || size->x > 16384 || size->y > 16384)
        throwInputError("", "--size", "the window must be between 320x240 and 16384x16384, got \"" + text + "\"");
    return *size;
}

int runView(const ViewOptions& options) {
    viewer::ViewerOptions viewerOptions;
    viewerOptions.inputs = options.inputs;
    viewerOptions.maxGpuMemoryBytes = parseGpuMemoryOption(options.gpuMemory);
    viewerOptions.readOptions = toReadOptions(options.dataset);
    viewerOptions.dataDirectory = bundledDataDirectory();
    viewerOptions.script = options.script;
    viewerOptions.windowSize = parseWindowSize(options.size);
    viewerOptions.shaderDirectory = options.shaderDirectory;
    viewerOptions.vsync = !options.noVsync;
    viewerOptions.adjustFirstScene = [overrides = options.overrides](Scene& scene, const Series& series,
                                                                     bool automaticScene) {
        applyRayOverrides(scene, series, automaticScene, overrides);
    };
    return viewer::runViewer(viewerOptions);
}

}  // namespace

Command addViewCommand(CLI::App& app) {
    auto options = std::make_shared<ViewOptions>();
    CLI::App* command = app.add_subcommand(
        "view", "Open the interactive viewer on a scene or dataset (default: the bundled Figure 1 scene)");
    command->add_option("input", options->inputs,
                        std::string("Scene file (JSON); or a dataset: ") + datasetKindsText());
    command->add_option("--script", options->script,
                        "Play input events from this file (format: docs/viewer.md), e.g. for tests")
        ->check(CLI::ExistingFile);
    command->add_option("--size", options->size, "Window size in screen pixels, WIDTHxHEIGHT")
        ->capture_default_str();
    command->add_flag("--no-vsync", options->noVsync, "Do not wait for the display's refresh between frames");
    addShaderDirectoryOption(*command, options->shaderDirectory);
    addRayOverrides(*command, options->overrides);
    addDatasetOptions(*command, options->dataset);
    addGpuMemoryOption(*command, options->gpuMemory);
    return {command, [options] { return runView(*options); }};
}

}  // namespace tstyles::cli
