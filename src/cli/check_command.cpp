// `tstyles check SUITE`: renders every scene of a regression suite headless (--jobs cases at once,
// check_runner.h), compares it with its golden image, prints a line per case as it finishes and a
// table in suite order, writes a report folder (images of what failed, an HTML page, JUnit XML)
// and exits 0 when all pass, 1 otherwise; --update writes new goldens.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>

#include "check_report.h"
#include "check_runner.h"
#include "check_suite.h"
#include "commands.h"
#include "tstyles/core/errors.h"
#include "tstyles/image/image_io.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::cli {
namespace {

namespace fs = std::filesystem;

struct CheckOptions {
    fs::path suite;
    fs::path report = "check-report";
    std::vector<std::string> update;  // case names whose golden is rewritten
    bool updateAll = false;
    std::string jobs = "auto";  // cases at once: a number >= 1, or auto (check_runner.h)
    GlOptions gl;
};

void printTable(const std::vector<CaseResult>& results) {
    for (std::size_t i = 0; i < results.size(); ++i) {
        const CaseResult& result = results[i];
        std::cout << "[" << i + 1 << "/" << results.size() << "] " << std::left << std::setw(40) << result.name
                  << std::setw(10) << toString(result.outcome)
                  << (result.difference ? "max " + std::to_string(result.difference->maxDelta) + "/255, SSIM " +
                                              std::to_string(result.difference->ssim)
                                        : std::string())
                  << std::fixed << std::setprecision(2) << "  (" << result.seconds << " s)\n"
                  << std::defaultfloat << std::setprecision(6);
        for (const std::string& problem : result.problems) std::cout << "        " << problem << "\n";
    }
}

int runCheck(CheckOptions options) {
    const std::optional<int> jobs = parseJobs(options.jobs);
    const CheckSuite suite = loadCheckSuite(options.suite);
    std::set<std::string> names;
    for (const CheckCase& entry : suite.cases) names.insert(entry.name);
    for (const std::string& name : options.update)
        if (!names.count(name)) throwInputError(suite.file, "--update", "the suite has no case named \"" + name + "\"");
    requireReplaceableReportFolder(options.report);
    // Every scene is read before anything is rendered: a bad one fails the run at once, named.
    std::vector<Scene> scenes;
    std::vector<bool> update;
    for (const CheckCase& entry : suite.cases) {
        scenes.push_back(loadScene(entry.scene));
        update.push_back(options.updateAll || std::find(options.update.begin(), options.update.end(), entry.name) !=
                                                  options.update.end());
    }
    CaseRun run = runCases(suite, scenes, update,
                           {jobs, parseBackend(options.gl.backend),
                            ShaderLibrary::fromEnvironment(options.gl.shaderDirectory)},
                           std::cout);
    std::cout << "\n";
    printTable(run.results);
    // Goldens are written once every case has rendered, in suite order: cases compare with the
    // goldens as the run found them, and of two cases sharing a golden the later one wins, as
    // with one case at a time.
    int failed = 0;
    for (std::size_t i = 0; i < run.results.size(); ++i) {
        const CaseResult& result = run.results[i];
        if (result.outcome == CaseOutcome::Updated) writeImage(*result.actual, suite.cases[i].golden);
        failed += result.outcome == CaseOutcome::Failed || result.outcome == CaseOutcome::MissingGolden;
    }
    writeCheckReport(options.report, suite.name, run.results);
    std::cout << (failed == 0 ? "all " + std::to_string(run.results.size()) + " cases pass"
                              : std::to_string(failed) + " of " + std::to_string(run.results.size()) + " cases fail")
              << "; report: " << (options.report / "index.html").string() << ", "
              << (options.report / "junit.xml").string() << " (" << run.context << ")\n";
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
    command->add_option("--jobs", options->jobs,
                        "Cases rendered at once, each on its own GL context: a number >= 1, or auto (1 on "
                        "llvmpipe/softpipe, else up to 4)")
        ->capture_default_str();
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
