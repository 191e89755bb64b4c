// Scene files or automatic scenes, and command-line overrides (scene_source.h).
#include "scene_source.h"


#include <algorithm>
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

// One line per ray mode: its name and what it shows.
std::string rayModeHelp() {
    std::string help = "How the samples along a ray become the pixel (docs/ray-modes.md):";
    for (const RayModeInfo& info : rayModes()) help += std::string("\n  ") + info.name + ": " + info.summary;
    return help;
}

// The scene's ray mode with --ray and --ray-KEY applied, read by the scene reader as the same keys
// in a file are, and checked beside the scene's compositor.
void readRayOverrides(Scene& scene, const SceneOverrides& overrides) {
    const std::string mode = overrides.rayMode.value_or(toString(scene.rayMode));
    nlohmann::json ray = {{"mode", mode}};
    std::vector<std::string> given;
    for (const auto& [key, text] : overrides.rayOptions)
        if (text) {
            ray[key] = valueFromText(*text);
            // A single number for a list.
            const RayModeOption* option = rayModeInfo(*rayModeFromString(mode)).options.find(key);
            if (option && option->kind == RayModeOptionKind::NumberList && !ray[key].is_array())
                ray[key] = nlohmann::json::array({ray[key]});
            given.push_back(key);
        }
    // The scene's own options of that mode stay, but a list that follows another's length goes where
    // that one was given anew.
    if (const RayModeInfo* info = overrides.rayMode ? nullptr : &rayModeInfo(scene.rayMode))
        for (const RayModeOption& option : info->options) {
            if (ray.contains(option.key)) continue;
            if (option.countOf && ray.contains(option.countOf)) continue;
            ray[option.key] = option.kind == RayModeOptionKind::Number
                                  ? nlohmann::json(scene.rayOptions.number(option))
                                  : nlohmann::json(scene.rayOptions.numbers(option));
        }
    const nlohmann::json snippet = {{"dataset", "-"}, {"ray", ray}};
    Scene read;
    try {
        read = parseScene(snippet.dump(), "");
    } catch (const InputError& error) {
        std::string message = error.what();
        std::string field = "--ray";
        for (const std::string& key : given)
            if (message.rfind("ray." + key, 0) == 0) field = "--ray-" + key;
        if (const std::size_t colon = message.find(": "); message.rfind("ray", 0) == 0 && colon != std::string::npos)
            message.erase(0, colon + 2);
        throwInputError("", field, message);
    }
    scene.rayMode = read.rayMode;
    scene.rayOptions = read.rayOptions;
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

void addRayOverrides(CLI::App& command, SceneOverrides& overrides) {
    command.add_option("--ray", overrides.rayMode, rayModeHelp())->check(CLI::IsMember(rayModeNames()));
    for (const RayModeOption* option : rayModeOptionsOfAll()) {
        std::optional<std::string>& value = overrides.rayOptions[option->key];
        const std::string takers = listedNames(rayModesTaking(option->key));
        command.add_option(std::string("--ray-") + option->key, value,
                           std::string("Ray mode ") + takers + ": " + option->help +
                               (option->kind == RayModeOptionKind::NumberList
                                    ? " (1 to " + std::to_string(option->maxCount) + " numbers, comma-separated)"
                                    : std::string(" (") + option->range.describe() + ")"));
    }
}

void addSceneOverrides(CLI::App& command, SceneOverrides& overrides) {
    command.add_option("--tc", overrides.compositor, compositorHelp())->check(CLI::IsMember(temporalCompositorNames()));
    addRayOverrides(command, overrides);
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

std::optional<std::string> applyRayOverrides(Scene& scene, const Series& series, bool automaticScene,
                                             const SceneOverrides& overrides) {
    const bool rayGiven = overrides.rayMode || std::any_of(overrides.rayOptions.begin(), overrides.rayOptions.end(),
                                                           [](const auto& option) { return option.second.has_value(); });
    std::optional<std::string> explanation;
    if (rayGiven) {
        readRayOverrides(scene, overrides);
        if (automaticScene) {
            // The automatic STF follows the mode, as the automatic scene would have made it.
            applyAutomaticRay(scene, series, automaticOpacityWindow(series), scene.rayMode);
            explanation = "ray " + toString(scene.rayMode) + " (--ray): " + rayModeInfo(scene.rayMode).summary;
        }
    }
    // A compositor chosen for a file's automatic scene that its automatic mode does not go with
    // (the average on a map or an MR): the rays composite, as the viewer does, and the STF follows.
    if (automaticScene && overrides.compositor && !rayGiven)
        if (const auto problem = rayModeProblem(scene); problem && problem->key == "ray.mode") {
            const std::string automaticMode = toString(scene.rayMode);
            scene.rayMode = kCompositeRay;
            applyAutomaticRay(scene, series, automaticOpacityWindow(series), kCompositeRay);
            explanation = "ray composite: " + toString(scene.compositor) + " (--tc) does not go with " +
                          automaticMode + ", the file's automatic mode";
        }
    if (overrides.compositor || rayGiven)
        if (const auto problem = rayModeProblem(scene))
            throwInputError("", overrides.rayMode || !overrides.compositor ? "--ray" : "--tc",
                            problem->key + ": " + problem->problem);
    return explanation;
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
    const std::optional<std::string> rayLine =
        applyRayOverrides(scene, opened.series, !opened.explanation.empty(), overrides);
    if (rayLine) opened.explanation.push_back(*rayLine);
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
                                  const DatasetOptions& datasetOptions, RenderedBy renderedBy) {
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
    AutomaticScene automatic =
        automaticScene(series, userAbsolutePath({}, inputs.front()), automaticOpacityWindow(series), renderedBy);
    return {std::move(automatic.scene), std::move(series), std::move(automatic.explanation)};
}

}  // namespace tstyles::cli
