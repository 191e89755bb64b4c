// Reading check suites: a JSON file of cases, or a folder of scenes with their goldens.
#include "check_suite.h"

#include <algorithm>
#include <set>

#include "comparison_thresholds.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace tstyles::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

int sideIn(const json& value, const fs::path& file, const std::string& field) {
    if (!value.is_number_integer() || value.get<int>() < 1 || value.get<int>() > 16384)
        throwInputError(file, field, "expected a whole number of pixels in [1, 16384]");
    return value.get<int>();
}

std::string textIn(const json& value, const fs::path& file, const std::string& field) {
    if (!value.is_string() || value.get<std::string>().empty()) throwInputError(file, field, "expected a non-empty string");
    return value.get<std::string>();
}

// A file named in the suite: also a name the system can look up.
std::string pathIn(const json& value, const fs::path& file, const std::string& field) {
    std::string text = textIn(value, file, field);
    requireUsablePathName({file, field}, text);
    return text;
}

CheckCase readCase(const json& entry, const fs::path& file, const std::string& field, const ComparisonThresholds& base) {
    if (!entry.is_object()) throwInputError(file, field, "expected an object with at least \"scene\"");
    const fs::path folder = file.parent_path();
    CheckCase result;
    result.thresholds = base;
    for (const auto& [key, value] : entry.items()) {
        const std::string keyField = field + "." + key;
        if (key == "scene") result.scene = (folder / pathIn(value, file, keyField)).lexically_normal();
        else if (key == "golden") result.golden = (folder / pathIn(value, file, keyField)).lexically_normal();
        else if (key == "name") result.name = textIn(value, file, keyField);
        else if (key == "width") result.width = sideIn(value, file, keyField);
        else if (key == "height") result.height = sideIn(value, file, keyField);
        else if (key == "thresholds") result.thresholds = thresholdsFromJson(value, base, file, keyField);
        else throwInputError(file, keyField, "unknown key; allowed: scene, golden, name, width, height, thresholds");
    }
    if (result.scene.empty()) throwInputError(file, field + ".scene", "missing; every case names its scene file");
    if (userPathKind({file, field + ".scene"}, result.scene) != PathKind::RegularFile)
        throwInputError(file, field + ".scene", "no such scene file: " + result.scene.string());
    if (result.name.empty()) result.name = result.scene.stem().string();
    if (result.golden.empty()) result.golden = folder / (result.name + ".png");
    return result;
}

CheckSuite readSuiteFile(const fs::path& file) {
    const json root = readJsonFile(file);
    if (!root.is_object()) throwInputError(file, "", "expected an object with \"cases\"");
    CheckSuite suite{file.stem().string(), file, {}};
    ComparisonThresholds base;
    for (const auto& [key, value] : root.items())
        if (key != "thresholds" && key != "cases") throwInputError(file, key, "unknown key; allowed: thresholds, cases");
    if (const auto thresholds = root.find("thresholds"); thresholds != root.end())
        base = thresholdsFromJson(*thresholds, base, file, "thresholds");
    const auto cases = root.find("cases");
    if (cases == root.end() || !cases->is_array() || cases->empty())
        throwInputError(file, "cases", "expected a non-empty array of cases");
    for (std::size_t i = 0; i < cases->size(); ++i)
        suite.cases.push_back(readCase((*cases)[i], file, "cases[" + std::to_string(i) + "]", base));
    return suite;
}

CheckSuite readSuiteFolder(const fs::path& folder) {
    CheckSuite suite{folder.filename().string(), folder, {}};
    ComparisonThresholds base;
    if (userPathKind({}, folder / "thresholds.json") == PathKind::RegularFile)
        base = thresholdsFromJson(readJsonFile(folder / "thresholds.json"), base, folder / "thresholds.json", "");
    std::vector<fs::path> scenes;
    std::error_code error;
    for (const fs::directory_entry& entry : withUserPath({}, folder, [&] { return fs::directory_iterator(folder); }))
        if (entry.is_regular_file(error) && entry.path().extension() == ".json" &&
            entry.path().filename() != "thresholds.json")
            scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    if (scenes.empty()) throwInputError(folder, "", "holds no scene files (*.json) to check");
    for (const fs::path& scene : scenes) {
        CheckCase entry;
        entry.name = scene.stem().string();
        entry.scene = scene;
        entry.golden = folder / "golden" / (entry.name + ".png");
        entry.thresholds = base;
        suite.cases.push_back(entry);
    }
    return suite;
}

}  // namespace

CheckSuite loadCheckSuite(const fs::path& suitePath) {
    const PathKind kind = userPathKind({}, suitePath);
    if (kind == PathKind::Missing) throwInputError(suitePath, "", "no such suite file or folder");
    const fs::path absolute = userAbsolutePath({}, suitePath);
    CheckSuite suite = kind == PathKind::Folder ? readSuiteFolder(absolute) : readSuiteFile(absolute);
    std::set<std::string> names;
    for (const CheckCase& entry : suite.cases)
        if (!names.insert(entry.name).second)
            throwInputError(suite.file, "cases", "two cases are named \"" + entry.name + "\"; names must differ");
    return suite;
}

}  // namespace tstyles::cli
