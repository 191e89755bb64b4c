// A screenshot regression suite for `tstyles check` (docs/ci.md): scenes, their golden images and
// the thresholds they are held to, from a JSON file or a folder of scenes.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/image/image_comparison.h"

namespace tstyles::cli {

struct CheckCase {
    std::string name;
    std::filesystem::path scene;
    std::filesystem::path golden;
    std::optional<int> width;   // overrides the scene's image size
    std::optional<int> height;
    ComparisonThresholds thresholds;
};

struct CheckSuite {
    std::string name;  // the suite file's (or folder's) stem
    std::filesystem::path file;
    std::vector<CheckCase> cases;
};

// A suite file:
//   {"thresholds": {...}, "cases": [{"scene": "a.json", "golden": "golden/a.png", "name": "a",
//    "width": 256, "height": 256, "thresholds": {...}}, ...]}
// paths relative to the file's folder; or a folder: every *.json scene in it, goldens in
// golden/<name>.png, thresholds from thresholds.json where there is one. InputError naming the
// file and key for an unknown key, a missing scene, or two cases of one name.
CheckSuite loadCheckSuite(const std::filesystem::path& suite);

}  // namespace tstyles::cli
