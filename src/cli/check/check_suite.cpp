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

// The suite's thresholds, and those of each renderer entry over them.
struct SuiteThresholds {
    ComparisonThresholds base;
    std::vector<RendererThresholds> renderers;
};

CheckCase readCase(const json& entry, const fs::path& file, const std::string& field, const SuiteThresholds& suite) {
    if (!entry.is_object()) throwInputError(file, field, "expected an object with at least \"scene\"");
    const fs::path folder = file.parent_path();
    CheckCase result;
    result.thresholds = suite.base;
    result.rendererThresholds = suite.renderers;
    for (const auto& [key, value] : entry.items()) {
        const std::string keyField = field + "." + key;
        if (key == "scene") result.scene = (folder / pathIn(value, file, keyField)).lexically_normal();
        else if (key == "golden") result.golden = (folder / pathIn(value, file, keyField)).lexically_normal();
        else if (key == "name") result.name = textIn(value, file, keyField);
        else if (key == "width") result.width = sideIn(value, file, keyField);
        else if (key == "height") result.height = sideIn(value, file, keyField);
        else if (key == "thresholds") {
            result.thresholds = thresholdsFromJson(value, suite.base, file, keyField);
            for (std::size_t i = 0; i < suite.renderers.size(); ++i)
                result.rendererThresholds[i].thresholds =
                    thresholdsFromJson(value, suite.renderers[i].thresholds, file, keyField);
        }
        else throwInputError(file, keyField, "unknown key; allowed: scene, golden, name, width, height, thresholds");
    }
    if (result.scene.empty()) throwInputError(file, field + ".scene", "missing; every case names its scene file");
    if (userPathKind({file, field + ".scene"}, result.scene) != PathKind::RegularFile)
        throwInputError(file, field + ".scene", "no such scene file: " + result.scene.string());
    if (result.name.empty()) result.name = result.scene.stem().string();
    if (result.golden.empty()) result.golden = folder / (result.name + ".png");
    return result;
}

// "renderer_thresholds": [{"renderer": "llvmpipe", "thresholds": {...}}, ...], each over `base`.
void readRendererThresholds(const json& entries, const fs::path& file, SuiteThresholds& thresholds) {
    if (!entries.is_array())
        throwInputError(file, "renderer_thresholds", "expected an array of {\"renderer\", \"thresholds\"}");
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const std::string field = "renderer_thresholds[" + std::to_string(i) + "]";
        const json& entry = entries[i];
        if (!entry.is_object()) throwInputError(file, field, "expected an object {\"renderer\", \"thresholds\"}");
        for (const auto& [key, value] : entry.items())
            if (key != "renderer" && key != "thresholds")
                throwInputError(file, field + "." + key, "unknown key; allowed: renderer, thresholds");
        const auto renderer = entry.find("renderer");
        if (renderer == entry.end())
            throwInputError(file, field + ".renderer", "missing; a text that GL_RENDERER contains, e.g. \"llvmpipe\"");
        const auto values = entry.find("thresholds");
        if (values == entry.end())
            throwInputError(file, field + ".thresholds", "missing; the thresholds on that renderer");
        thresholds.renderers.push_back({textIn(*renderer, file, field + ".renderer"),
                                        thresholdsFromJson(*values, thresholds.base, file, field + ".thresholds")});
    }
}

CheckSuite readSuiteFile(const fs::path& file) {
    const json root = readJsonFile(file);
    if (!root.is_object()) throwInputError(file, "", "expected an object with \"cases\"");
    CheckSuite suite{file.stem().string(), file, {}};
    SuiteThresholds thresholds;
    for (const auto& [key, value] : root.items())
        if (key != "thresholds" && key != "renderer_thresholds" && key != "cases")
            throwInputError(file, key, "unknown key; allowed: thresholds, renderer_thresholds, cases");
    if (const auto base = root.find("thresholds"); base != root.end())
        thresholds.base = thresholdsFromJson(*base, thresholds.base, file, "thresholds");
    if (const auto renderers = root.find("renderer_thresholds"); renderers != root.end())
        readRendererThresholds(*renderers, file, thresholds);
    const auto cases = root.find("cases");
    if (cases == root.end() || !cases->is_array() || cases->empty())
        throwInputError(file, "cases", "expected a non-empty array of cases");
    for (std::size_t i = 0; i < cases->size(); ++i)
        suite.cases.push_back(readCase((*cases)[i], file, "cases[" + std::to_string(i) + "]", thresholds));
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

ChosenThresholds thresholdsOn(const CheckCase& entry, const std::string& glRenderer) {
    for (const RendererThresholds& candidate : entry.rendererThresholds)
        if (glRenderer.find(candidate.renderer) != std::string::npos) return {candidate.thresholds, candidate.renderer};
    return {entry.thresholds, std::nullopt};
}

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
