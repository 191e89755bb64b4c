// Reading check suites: a JSON file of cases, or a folder of scenes with their goldens.
#include "check_suite.h"

#include <algorithm>
#include <set>

#include "comparison_thresholds.h"
#include "tstyles/core/json_field.h"
#include "tstyles/core/json_text.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace tstyles::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

int sideIn(const JsonField& side) {
    const int pixels = side.integer();
    if (pixels < 1 || pixels > 16384) side.fail("expected a whole number of pixels in [1, 16384]");
    return pixels;
}

std::string textIn(const JsonField& text) {
    std::string value = text.string();
    if (value.empty()) text.fail("expected a non-empty string");
    return value;
}

// A file named in the suite, relative to the suite's folder: also a name the system can look up.
fs::path pathIn(const JsonField& name) {
    const std::string text = textIn(name);
    requireUsablePathName({name.file(), name.path()}, text);
    return (name.file().parent_path() / text).lexically_normal();
}

// The suite's thresholds, and those of each renderer entry over them.
struct SuiteThresholds {
    ComparisonThresholds base;
    std::vector<RendererThresholds> renderers;
};

CheckCase readCase(const JsonField& entry, const SuiteThresholds& suite) {
    entry.allowOnlyKeys({"scene", "golden", "name", "width", "height", "thresholds"});
    CheckCase result;
    result.thresholds = suite.base;
    result.rendererThresholds = suite.renderers;
    const JsonField scene = entry.member("scene", "missing; every case names its scene file");
    result.scene = pathIn(scene);
    if (const auto golden = entry.optionalMember("golden")) result.golden = pathIn(*golden);
    if (const auto name = entry.optionalMember("name")) result.name = textIn(*name);
    if (const auto width = entry.optionalMember("width")) result.width = sideIn(*width);
    if (const auto height = entry.optionalMember("height")) result.height = sideIn(*height);
    if (const auto thresholds = entry.optionalMember("thresholds")) {
        result.thresholds = thresholdsFromJson(*thresholds, suite.base);
        for (std::size_t i = 0; i < suite.renderers.size(); ++i)
            result.rendererThresholds[i].thresholds = thresholdsFromJson(*thresholds, suite.renderers[i].thresholds);
    }
    if (userPathKind({scene.file(), scene.path()}, result.scene) != PathKind::RegularFile)
        scene.fail("no such scene file: " + result.scene.string());
    if (result.name.empty()) result.name = result.scene.stem().string();
    if (result.golden.empty()) result.golden = entry.file().parent_path() / (result.name + ".png");
    return result;
}

// "renderer_thresholds": [{"renderer": "llvmpipe", "thresholds": {...}}, ...], each over `base`.
void readRendererThresholds(const JsonField& entries, SuiteThresholds& thresholds) {
    for (std::size_t i = 0; i < entries.arraySize(); ++i) {
        const JsonField entry = entries.element(i);
        entry.allowOnlyKeys({"renderer", "thresholds"});
        const JsonField renderer =
            entry.member("renderer", "missing; a text that GL_RENDERER contains, e.g. \"llvmpipe\"");
        const JsonField values = entry.member("thresholds", "missing; the thresholds on that renderer");
        thresholds.renderers.push_back({textIn(renderer), thresholdsFromJson(values, thresholds.base)});
    }
}

CheckSuite readSuiteFile(const fs::path& file) {
    const json document = readJsonFile(file, "check suite", JsonComments::Allowed);
    const JsonField root(file, document, "");
    root.allowOnlyKeys({"thresholds", "renderer_thresholds", "cases"});
    CheckSuite suite{file.stem().string(), file, {}};
    SuiteThresholds thresholds;
    if (const auto base = root.optionalMember("thresholds"))
        thresholds.base = thresholdsFromJson(*base, thresholds.base);
    if (const auto renderers = root.optionalMember("renderer_thresholds"))
        readRendererThresholds(*renderers, thresholds);
    const JsonField cases = root.member("cases", "missing; expected a non-empty array of cases");
    if (cases.arraySize() == 0) cases.fail("expected a non-empty array of cases");
    for (std::size_t i = 0; i < cases.arraySize(); ++i) suite.cases.push_back(readCase(cases.element(i), thresholds));
    return suite;
}

CheckSuite readSuiteFolder(const fs::path& folder) {
    CheckSuite suite{folder.filename().string(), folder, {}};
    ComparisonThresholds base;
    if (const fs::path file = folder / "thresholds.json"; userPathKind({}, file) == PathKind::RegularFile) {
        const json document = readJsonFile(file, "thresholds file", JsonComments::Allowed);
        base = thresholdsFromJson(JsonField(file, document, ""), base);
    }
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
