// A screenshot regression suite for `tstyles check` (docs/ci.md): scenes, their golden images and
// the thresholds they are held to, from a JSON file or a folder of scenes.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/image/image_comparison.h"

namespace tstyles::cli {

// Thresholds for a renderer whose GL_RENDERER contains `renderer` (the goldens' renderer can be
// held to exact ones, other drivers to looser ones).
struct RendererThresholds {
    std::string renderer;
    ComparisonThresholds thresholds;
};

struct CheckCase {
    std::string name;
    std::filesystem::path scene;
    std::filesystem::path golden;
    std::optional<int> width;   // overrides the scene's image size
    std::optional<int> height;
    ComparisonThresholds thresholds;  // on a renderer that no entry of the suite's renderer_thresholds names
    // The suite's renderer_thresholds in order, each with the case's own thresholds on top: the first
    // whose text GL_RENDERER contains applies.
    std::vector<RendererThresholds> rendererThresholds;
};

struct CheckSuite {
    std::string name;  // the suite file's (or folder's) stem
    std::filesystem::path file;
    std::vector<CheckCase> cases;
};

// The thresholds a case is held to on `glRenderer` (GL_RENDERER, with the version or not), and the
// renderer_thresholds entry that chose them (none: the suite's own).
struct ChosenThresholds {
    const ComparisonThresholds& thresholds;
    std::optional<std::string> renderer;
};
ChosenThresholds thresholdsOn(const CheckCase& entry, const std::string& glRenderer);

// A suite file:
//   {"thresholds": {...},
//    "renderer_thresholds": [{"renderer": "llvmpipe", "thresholds": {...}}, ...],
//    "cases": [{"scene": "a.json", "golden": "golden/a.png", "name": "a",
//               "width": 256, "height": 256, "thresholds": {...}}, ...]}
// paths relative to the file's folder; a renderer entry's thresholds replace the suite's keys it
// names, and a case's own replace either; or a folder: every *.json scene in it, goldens in
// golden/<name>.png, thresholds from thresholds.json where there is one. InputError naming the
// file and key for an unknown key, a missing scene, or two cases of one name.
CheckSuite loadCheckSuite(const std::filesystem::path& suite);

}  // namespace tstyles::cli
