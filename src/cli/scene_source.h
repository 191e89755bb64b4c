// What `render`, `view` and `scene` draw: a scene file with its dataset, or datasets with the
// automatic scene (docs/automatic-scene.md), and the command-line overrides of a scene's choices.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli11_forward.h"

#include "commands.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/scene.h"

namespace tstyles::cli {

// Overrides of what a scene (automatic or from a file) says, spelled as the scene keys are.
struct SceneOverrides {
    std::optional<std::string> compositor;             // --tc
    std::optional<std::string> rayMode;                // --ray
    // --ray-KEY of each ray mode option (ray_modes.h), by KEY, as typed ("0.3,0.6").
    std::map<std::string, std::optional<std::string>> rayOptions;
    std::optional<std::string> orientation;            // --orientation data|auto|+x,+z,-y
    std::optional<std::string> aspect;                 // --aspect physical|cubic|auto|SX,SY,SZ
    std::optional<std::string> verticalExaggeration;   // --vertical-exaggeration X|auto
    std::optional<std::string> unchanged;              // --unchanged auto|off|CHANGE
    std::optional<double> unchangedOpacity;            // --unchanged-opacity SHARE
};
void addSceneOverrides(CLI::App& command, SceneOverrides& overrides);
// --ray and its --ray-KEY options alone (`view` takes these and no other override).
void addRayOverrides(CLI::App& command, SceneOverrides& overrides);

struct SceneAndSeries {
    Scene scene;
    Series series;  // as read, before the scene's display frame
    // The automatic scene's choices, one line each; empty for a scene file.
    std::vector<std::string> explanation;
};

// An automatic scene's gradient TSTF follows a compositor chosen here (a diverging one for signed
// values); a scene file's stays as written.
void applySceneOverrides(SceneAndSeries& opened, const SceneOverrides& overrides);
// --ray and --ray-KEY (and the check of the ray mode beside --tc's compositor): an automatic
// scene's STF follows the mode, and the line that says so for its explanation is returned.
std::optional<std::string> applyRayOverrides(Scene& scene, const Series& series, bool automaticScene,
                                             const SceneOverrides& overrides);

// One scene file (its dataset, or `datasetFiles` instead), else the inputs are the files of one
// dataset and the scene is the automatic one (whose rays composite where the processes' frames
// are merged: RenderedBy::MergedBlocks).
SceneAndSeries openSceneOrDataset(const std::vector<std::filesystem::path>& inputs,
                                  const std::vector<std::filesystem::path>& datasetFiles,
                                  const DatasetOptions& datasetOptions,
                                  RenderedBy renderedBy = RenderedBy::OneProcess);

}  // namespace tstyles::cli
