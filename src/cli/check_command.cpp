// `tstyles check SUITE`: renders every scene of a regression suite headless, compares it with its
// golden image, prints a line per case, writes a report folder (images of what failed, an HTML
// page, JUnit XML) and exits 0 when all pass, 1 otherwise; --update writes new goldens.
#include <chrono>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "check_report.h"
#include "check_suite.h"
#include "commands.h"
#include "tstyles/core/errors.h"
#include "tstyles/image/image_io.h"
#include "tstyles/render/annotated_rendering.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::cli {
namespace {

namespace fs = std::filesystem;

struct CheckOptions {
    fs::path suite;
    fs::path report = "check-report";
    std::vector<std::string> update;  // case names whose golden is rewritten
    bool updateAll = false;
    GlOptions gl;
};

// Scenes' series, read once per dataset, and the one on the GPU.
class SeriesCache {
public:
    explicit SeriesCache(Renderer& renderer) : renderer_(renderer) {}
    // The scene fitted to its dataset, uploaded unless it is the series already there.
    const SceneOnSeries& fit(const Scene& scene) {
        auto raw = raw_.find(scene.dataset);
        if (raw == raw_.end()) raw = raw_.emplace(scene.dataset, openDataset({scene.dataset}, DatasetOptions{})).first;
        const bool sameSeries = fitted_ && uploaded_ == scene.dataset && fitted_->scene.display == scene.display;
        Series copy = raw->second;
        fitted_.emplace(fitSceneToSeries(scene, std::move(copy)));
        if (!sameSeries) renderer_.setSeries(fitted_->series);
        uploaded_ = scene.dataset;
        return *fitted_;
    }

private:
    Renderer& renderer_;
    std::map<fs::path, Series> raw_;
    std::optional<SceneOnSeries> fitted_;
    fs::path uploaded_;
};

CaseResult checkCase(const CheckCase& entry, Scene scene, SeriesCache& cache, Renderer& renderer, bool update) {
    const auto start = std::chrono::steady_clock::now();
    CaseResult result{entry.name, entry.scene};
    if (entry.width) scene.width = *entry.width;
    if (entry.height) scene.height = *entry.height;
    const SceneOnSeries& fitted = cache.fit(scene);
    AnnotatedRendering rendering(renderer, fitted);
    Image actual = rendering.render(fitted.scene);
    const bool haveGolden = fs::is_regular_file(entry.golden);
    std::optional<Image> expected;
    if (haveGolden) expected = readImage(entry.golden);
    if (expected && expected->width == actual.width && expected->height == actual.height)
        result.difference = compareImages(actual, *expected, entry.thresholds.pixelThreshold);
    if (update) {
        writeImage(actual, entry.golden);
        result.outcome = CaseOutcome::Updated;
        result.problems.push_back(!haveGolden ? "new golden " + entry.golden.string()
                                  : result.difference ? "golden rewritten; it changed by " + describe(*result.difference)
                                                      : "golden rewritten at a new size");
    } else if (!expected) {
        result.outcome = CaseOutcome::MissingGolden;
        result.problems.push_back("no golden image at " + entry.golden.string() + "; --update " + entry.name +
                                  " writes it (look at it first)");
    } else if (!result.difference) {
        result.outcome = CaseOutcome::Failed;
        result.problems.push_back("the golden is " + std::to_string(expected->width) + "x" +
                                  std::to_string(expected->height) + ", the render " + std::to_string(actual.width) +
                                  "x" + std::to_string(actual.height));
    } else {
        result.problems = thresholdsExceeded(*result.difference, entry.thresholds);
        result.outcome = result.problems.empty() ? CaseOutcome::Passed : CaseOutcome::Failed;
    }
    if (result.outcome == CaseOutcome::Failed || result.outcome == CaseOutcome::MissingGolden) {
        result.expected = std::move(expected);
        result.actual = std::move(actual);
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

int runCheck(CheckOptions options) {
    const CheckSuite suite = loadCheckSuite(options.suite);
    std::set<std::string> names;
    for (const CheckCase& entry : suite.cases) names.insert(entry.name);
    for (const std::string& name : options.update)
        if (!names.count(name)) throwInputError(suite.file, "--update", "the suite has no case named \"" + name + "\"");
    requireReplaceableReportFolder(options.report);
    // Every scene is read before anything is rendered: a bad one fails the run at once, named.
    std::vector<Scene> scenes;
    for (const CheckCase& entry : suite.cases) scenes.push_back(loadScene(entry.scene));

    const auto context = createHeadlessContext(parseBackend(options.gl.backend), glDebugOutputRequested());
    Renderer renderer(ShaderLibrary::fromEnvironment(options.gl.shaderDirectory));
    SeriesCache cache(renderer);
    std::vector<CaseResult> results;
    int failed = 0;
    for (std::size_t i = 0; i < suite.cases.size(); ++i) {
        const CheckCase& entry = suite.cases[i];
        const bool update = options.updateAll ||
                            std::find(options.update.begin(), options.update.end(), entry.name) != options.update.end();
        results.push_back(checkCase(entry, scenes[i], cache, renderer, update));
        const CaseResult& result = results.back();
        failed += result.outcome == CaseOutcome::Failed || result.outcome == CaseOutcome::MissingGolden;
        std::cout << "[" << i + 1 << "/" << suite.cases.size() << "] " << std::left << std::setw(40) << entry.name
                  << std::setw(10) << toString(result.outcome)
                  << (result.difference ? "max " + std::to_string(result.difference->maxDelta) + "/255, SSIM " +
                                              std::to_string(result.difference->ssim)
                                        : std::string())
                  << std::fixed << std::setprecision(2) << "  (" << result.seconds << " s)\n"
                  << std::defaultfloat << std::setprecision(6);
        for (const std::string& problem : result.problems) std::cout << "        " << problem << "\n";
        std::cout.flush();
    }
    writeCheckReport(options.report, suite.name, results);
    std::cout << (failed == 0 ? "all " + std::to_string(results.size()) + " cases pass"
                              : std::to_string(failed) + " of " + std::to_string(results.size()) + " cases fail")
              << "; report: " << (options.report / "index.html").string() << ", "
              << (options.report / "junit.xml").string() << " (" << context->description() << ")\n";
    return failed == 0 ? kExitSuccess : kExitFailure;
}

}  // namespace

Command addCheckCommand(CLI::App& app) {
    auto options = std::make_shared<CheckOptions>();
    CLI::App* command = app.add_subcommand(
        "check", "Render a regression suite's scenes and compare them with their golden images (docs/ci.md)");
    command->add_option("suite", options->suite, "A suite file (JSON) or a folder of scenes with golden/ images")
        ->required();
    command->add_option("--report", options->report, "Folder for the report: index.html, junit.xml, images")
        ->capture_default_str();
    CLI::Option* update =
        command->add_option("--update", options->update, "Rewrite the golden images of these cases (look at them first)")
            ->delimiter(',')
            ->expected(0, -1);
    command->add_flag("--all", options->updateAll, "With --update: rewrite every case's golden image");
    addGlOptions(*command, options->gl);
    return {command, [options, update] {
                const bool updating = update->count() > 0;
                // `--update` with no names reads as one empty name.
                std::erase(options->update, std::string());
                if (options->updateAll && !updating)
                    throwInputError("", "--all", "goes with --update: --update --all rewrites every golden");
                if (updating && options->update.empty() && !options->updateAll)
                    throwInputError("", "--update", "name the cases whose goldens to rewrite, or add --all");
                return runCheck(*options);
            }};
}

}  // namespace tstyles::cli
