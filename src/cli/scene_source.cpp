// Scene files or automatic scenes, and command-line overrides (scene_source.h).
#include "scene_source.h"


#include <cstdlib>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/input_kind.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles::cli {
namespace {

// "auto" stays a string, "1.5" a number, "1,2,0.5" and "+x,+z,-y" arrays of numbers or strings.
nlohmann::json valueFromText(const std::string& text) {
    auto element = [](const std::string& part) -> nlohmann::json {
        char* end = nullptr;
        const double number = std::strtod(part.c_str(), &end);
        if (!part.empty() && end == part.c_str() + part.size()) return number;
        return part;
    };
    if (text.find(',') == std::string::npos) return element(text);
    nlohmann::json array = nlohmann::json::array();
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        array.push_back(element(text.substr(start, comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return array;
}

// The scene reader checks an override exactly as it checks the key in a file.
DisplaySettings displayFromOptions(const std::string& key, const std::string& option, const std::string& text) {
    const nlohmann::json snippet = {{"dataset", "-"}, {key, valueFromText(text)}};
    try {
        return parseScene(snippet.dump(), "").display;
    } catch (const InputError& error) {
        std::string message = error.what();
        if (message.rfind(key + ": ", 0) == 0) message.erase(0, key.size() + 2);
        throwInputError("", option, message);
    }
}

// One line per compositor: its name and what it shows.
std::string compositorHelp() {
    std::string help = "Temporal compositor (docs/compositors.md):";
    for (const TemporalCompositor compositor : builtInCompositors())
        help += std::string("\n  ") + compositorInfo(compositor).name + ": " + compositorInfo(compositor).summary;
    return help;
}

// The scene's unchanged-place setting with --unchanged and --unchanged-opacity applied, checked by
// the scene reader as the same keys in a file are.
std::optional<UnchangedTime> unchangedFromOptions(const Scene& scene, const SceneOverrides& overrides) {
    if (overrides.unchanged == "off") {
        if (overrides.unchangedOpacity)
            throwInputError("", "--unchanged-opacity", "says how unchanged places show, but --unchanged is off");
        return std::nullopt;
    }
    // The scene's own setting as the scene writer spells it, the options applied over it.
    const nlohmann::json written = nlohmann::json::parse(sceneToJson(scene, {}))["compositor"];
    nlohmann::json unchanged = written.is_object() && written.contains("unchanged") ? written["unchanged"]
                                                                                     : nlohmann::json::object();
    if (overrides.unchanged) {
        unchanged["below"] = valueFromText(*overrides.unchanged);
        if (unchanged["below"] == "auto") {
            unchanged.erase("tie");
            unchanged.erase("gain");
            unchanged.erase("boundary");
        }
    }
    if (overrides.unchangedOpacity) unchanged["opacity"] = *overrides.unchangedOpacity;
    const std::string option = overrides.unchanged ? "--unchanged" : "--unchanged-opacity";
    const nlohmann::json snippet = {{"dataset", "-"},
                                    {"compositor", {{"name", toString(scene.compositor)}, {"unchanged", unchanged}}}};
    try {
        return parseScene(snippet.dump(), "").compositorOptions.unchanged;
    } catch (const InputError& error) {
        std::string message = error.what();
        std::string field = option;
        if (message.rfind("compositor.unchanged.opacity: ", 0) == 0) field = "--unchanged-opacity";
        if (message.rfind("compositor.unchanged.below: ", 0) == 0) field = "--unchanged";
        for (const std::string key : {"compositor.unchanged.below: ", "compositor.unchanged.opacity: ",
                                      "compositor.unchanged: "})
            if (message.rfind(key, 0) == 0) message.erase(0, key.size());
        throwInputError("", field, message);
    }
}

std::string unchangedText(const std::optional<UnchangedTime>& unchanged) {
    std::string text = "unchanged places (--unchanged, --unchanged-opacity): ";
    if (!unchanged) return text + "time colours everywhere";
    text += unchanged->automatic ? "no time colour below a change fitted to the data"
                                 : "no time colour below a change of " + nlohmann::json(unchanged->below).dump() +
                                       " in density units";
    return text + ", neutral there at " + nlohmann::json(unchanged->opacity).dump() + " of the STF's opacity";
}

}  // namespace

void addSceneOverrides(CLI::App& command, SceneOverrides& overrides) {
    command.add_option("--tc", overrides.compositor, compositorHelp())->check(CLI::IsMember(temporalCompositorNames()));
    command.add_option("--orientation", overrides.orientation,
                       "Which data axes show as right, up and toward the viewer: auto (from the file's axis meaning), "
                       "data (as stored), or three signed axes such as +x,+z,-y");
    command.add_option("--aspect", overrides.aspect,
                       "Proportions: auto, physical, cubic (each axis the same length), or a scale per display axis SX,SY,SZ");
    command.add_option("--vertical-exaggeration", overrides.verticalExaggeration,
                       "Stretch the vertical (display up) axis by this factor, or auto");
    command.add_option("--unchanged", overrides.unchanged,
                       "Compositors that pick a time-step: no time colour where a place's densities change by no "
                       "more than this (0 to 1, in density units), or two time-steps tie; auto (fitted to the "
                       "data, the automatic scene's choice) or off (time colours everywhere)");
    command.add_option("--unchanged-opacity", overrides.unchangedOpacity,
                       "An unchanged place shows the STF alone with this share of its opacity: 1 as the STF has "
                       "it, 0 transparent");
}

void applySceneOverrides(SceneAndSeries& opened, const SceneOverrides& overrides) {
    Scene& scene = opened.scene;
    if (overrides.compositor) {
        scene.compositor = *temporalCompositorFromString(*overrides.compositor);
        if (!opened.explanation.empty()) {
            const std::string colours = applyAutomaticGradientColours(scene);
            const TemporalCompositorInfo& info = compositorInfo(scene.compositor);
            opened.explanation.push_back("compositor " + *overrides.compositor + " (--tc): " + info.summary +
                                         (info.reads == CompositorReads::GradientTstf ? "; " + colours : ""));
        }
    }
    if (overrides.unchanged || overrides.unchangedOpacity) {
        scene.compositorOptions.unchanged = unchangedFromOptions(scene, overrides);
        if (!opened.explanation.empty()) opened.explanation.push_back(unchangedText(scene.compositorOptions.unchanged));
    }
    if (overrides.orientation)
        scene.display.orientation = displayFromOptions("orientation", "--orientation", *overrides.orientation).orientation;
    if (overrides.aspect) scene.display.aspect = displayFromOptions("aspect", "--aspect", *overrides.aspect).aspect;
    if (overrides.verticalExaggeration)
        scene.display.verticalExaggeration =
            displayFromOptions("vertical_exaggeration", "--vertical-exaggeration", *overrides.verticalExaggeration)
                .verticalExaggeration;
}

SceneAndSeries openSceneOrDataset(const std::vector<std::filesystem::path>& inputs,
                                  const std::vector<std::filesystem::path>& datasetFiles,
                                  const DatasetOptions& datasetOptions) {
    if (inputs.size() == 1 && classifyInput(inputs.front()) == InputKind::Scene) {
        Scene scene = loadScene(inputs.front());
        Series series = openDataset(datasetFiles.empty() ? std::vector<std::filesystem::path>{scene.dataset} : datasetFiles,
                                    datasetOptions);
        return {std::move(scene), std::move(series), {}};
    }
    if (!datasetFiles.empty())
        throwInputError(inputs.front(), "--dataset", "replaces a scene file's dataset, but this input is a dataset itself");
    for (const auto& input : inputs)
        if (userPathKind({}, input) == PathKind::Missing) throwInputError(input, "", "no such file or folder");
    Series series = openDataset(inputs, datasetOptions);
    AutomaticScene automatic = automaticScene(series, userAbsolutePath({}, inputs.front()));
    return {std::move(automatic.scene), std::move(series), std::move(automatic.explanation)};
}

}  // namespace tstyles::cli
