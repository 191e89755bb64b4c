// `tstyles check SUITE`: renders every scene of a regression suite headless (--jobs cases at once,
// check_runner.h; or spread over MPI processes with --distributed, check_distributed.h), compares
// each with its golden image, prints a line per case as it finishes and a table in suite order,
// writes a report folder (images of what failed, an HTML page, JUnit XML) and exits 0 when all
// pass, 1 otherwise; --update writes new goldens.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <set>

#include <CLI/CLI.hpp>

#include "check_distributed.h"
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
    bool jobsGiven = false;     // --jobs on the command line (refused with --distributed)
    bool distributed = false;   // --distributed: the cases spread over MPI processes
    GlOptions gl;
};

struct PreparedCheck {
    CheckSuite suite;
    std::vector<Scene> scenes;  // one per case, read before anything renders
    std::vector<bool> update;   // per case: its golden is rewritten
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

// The suite and every scene read, the --update names and the report folder checked: a bad one fails
// the run before anything is rendered, named. `checkReportFolder`: only the process that writes
// the report checks its folder.
PreparedCheck prepareCheck(const CheckOptions& options, bool checkReportFolder) {
    PreparedCheck check{loadCheckSuite(options.suite), {}, {}};
    std::set<std::string> names;
    for (const CheckCase& entry : check.suite.cases) names.insert(entry.name);
    for (const std::string& name : options.update)
        if (!names.count(name))
            throwInputError(check.suite.file, "--update", "the suite has no case named \"" + name + "\"");
    if (checkReportFolder) requireReplaceableReportFolder(options.report);
    for (const CheckCase& entry : check.suite.cases) {
        check.scenes.push_back(loadScene(entry.scene));
        check.update.push_back(options.updateAll || std::find(options.update.begin(), options.update.end(),
                                                              entry.name) != options.update.end());
    }
    return check;
}

// After every case has rendered: the table, the goldens of --update, the report and the summary.
int finishCheck(const CheckOptions& options, const CheckSuite& suite, const CaseRun& run) {
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
    // run.context names GL_RENDERER: say which of the suite's thresholds held the cases.
    if (const auto renderer = thresholdsOn(suite.cases.front(), run.context).renderer)
        std::cout << "thresholds: the suite's renderer_thresholds for \"" << *renderer << "\"\n";
    return failed == 0 ? kExitSuccess : kExitFailure;
}

CaseRunOptions caseRunOptions(const CheckOptions& options, std::optional<int> jobs) {
    return {jobs, parseBackend(options.gl.backend), ShaderLibrary::fromEnvironment(options.gl.shaderDirectory)};
}

int runCheck(const CheckOptions& options) {
    const std::optional<int> jobs = parseJobs(options.jobs);
    const PreparedCheck check = prepareCheck(options, true);
    const CaseRun run = runCases(check.suite, check.scenes, check.update, caseRunOptions(options, jobs), std::cout);
    return finishCheck(options, check.suite, run);
}

// --distributed: process 0 reads and checks everything first, so that a bad suite is one message;
// then the others read it. Process 0 reports, writes the goldens and the report, and gives the
// exit code; the others exit 0 (main.cpp says why).
int runDistributedCheck(const CheckOptions& options) {
    const MpiSession mpi;
    std::optional<PreparedCheck> check;
    std::optional<CaseRunOptions> runOptions;
    mpi.together("reading the suite", [&] {
        if (!mpi.isFirst()) return;
        if (options.jobsGiven)
            throwInputError("", "--jobs",
                            "goes without --distributed: each process renders one case at a time; for more cases "
                            "at once, start more processes (mpirun -np N)");
        check = prepareCheck(options, true);
        runOptions = caseRunOptions(options, 1);
    });
    mpi.together("reading the suite", [&] {
        if (mpi.isFirst()) return;
        check = prepareCheck(options, false);
        runOptions = caseRunOptions(options, 1);
    });
    const CaseRun run = runCasesDistributed(mpi, check->suite, check->scenes, check->update, *runOptions, std::cout);
    if (!mpi.isFirst()) return kExitSuccess;
    return finishCheck(options, check->suite, run);
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
    CLI::Option* jobs = command
                            ->add_option("--jobs", options->jobs,
                                         "Cases rendered at once, each on its own GL context: a number >= 1, or "
                                         "auto (1 on llvmpipe/softpipe, else up to 4); not with --distributed")
                            ->capture_default_str();
    command->add_flag("--distributed", options->distributed,
                      "Spread the cases over the MPI processes this runs in (mpirun -np N tstyles check SUITE "
                      "--distributed): process r renders cases r+1, r+1+N, ... one at a time, process 0 reports "
                      "(docs/scaling.md); refuses --jobs");
    addGlOptions(*command, options->gl);
    return {command, [options, update, jobs] {
                const bool updating = update->count() > 0;
                // `--update` with no names reads as one empty name.
                std::erase(options->update, std::string());
                if (options->updateAll && !updating)
                    throwInputError("", "--all", "goes with --update: --update --all rewrites every golden");
                if (updating && options->update.empty() && !options->updateAll)
                    throwInputError("", "--update", "name the cases whose goldens to rewrite, or add --all");
                options->jobsGiven = jobs->count() > 0;
                return options->distributed ? runDistributedCheck(*options) : runCheck(*options);
            }};
}

}  // namespace tstyles::cli
