// `tstyles scene DATASET -o scene.json`: the automatic scene of a dataset written out, so that a
// user starts editing from what `render DATASET` and `view DATASET` show.
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "scene_source.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/data/format_listing.h"

namespace tstyles::cli {
namespace {

struct SceneOptions {
    std::vector<std::filesystem::path> inputs;
    std::filesystem::path output;
    SceneOverrides overrides;
    DatasetOptions dataset;
};

int runScene(const SceneOptions& options) {
    if (options.inputs.size() > 1)
        throwInputError(options.inputs.front(), "",
                        "a scene names one dataset; keep several files as one with `tstyles convert FILES -o FOLDER` "
                        "and make the scene of that folder");
    if (options.output.extension() != ".json")
        throwInputError(options.output, "-o", "a scene file is JSON: give it the extension .json");
    requireOutputFile({"", "-o"}, options.output, "scene file");
    SceneAndSeries opened = openSceneOrDataset(options.inputs, {}, options.dataset);
    if (opened.explanation.empty())
        throwInputError(options.inputs.front(), "", "is a scene file already; `tstyles scene` makes one from a dataset");
    applySceneOverrides(opened, options.overrides);
    saveScene(opened.scene, options.output);
    std::cout << "wrote " << options.output.string() << ", the automatic scene of " << options.inputs.front().string()
              << ":\n";
    for (const std::string& line : opened.explanation) std::cout << "  " << line << "\n";
    return kExitSuccess;
}

}  // namespace

Command addSceneCommand(CLI::App& app) {
    auto options = std::make_shared<SceneOptions>();
    CLI::App* command = app.add_subcommand(
        "scene", "Write the automatic scene of a dataset to a scene file, to edit and render (docs/automatic-scene.md)");
    command->add_option("dataset", options->inputs,
                        std::string("The dataset: ") + datasetKindsText())
        ->required();
    command->add_option("-o,--output", options->output, "Scene file to write (.json)")->required();
    addSceneOverrides(*command, options->overrides);
    addDatasetOptions(*command, options->dataset);
    return {command, [options] { return runScene(*options); }};
}

}  // namespace tstyles::cli
