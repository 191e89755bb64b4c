// The cases of a `tstyles check` run on several threads, each with its own headless context
// (`--jobs`), their results gathered in suite order whatever order they finish in.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "check_report.h"
#include "check_suite.h"
#include "tstyles/gl/headless_context.h"
#include "tstyles/gl/program.h"
#include "tstyles/scene/scene.h"

namespace tstyles::cli {

// `--jobs`: a whole number >= 1, or "auto" (nullopt). InputError naming --jobs otherwise.
std::optional<int> parseJobs(const std::string& text);

// How many cases run at once, and the line that says so and why.
struct Parallelism {
    int jobs = 1;
    std::string line;  // "4 parallel cases", "1 case at a time: llvmpipe already uses every core"
};

// Auto (nullopt): one case at a time on a software rasteriser (llvmpipe, softpipe: it already
// spreads one frame over every core, so more cases at once only add memory), else
// min(4, hardware threads). Never more jobs than cases.
Parallelism chooseParallelism(std::optional<int> requested, const std::string& glRenderer, std::size_t caseCount,
                              unsigned hardwareThreads);

struct CaseRunOptions {
    std::optional<int> jobs;  // nullopt: auto
    GlBackend backend = GlBackend::Auto;
    ShaderLibrary shaders;
};

struct CaseRun {
    std::vector<CaseResult> results;  // in suite order
    std::string context;              // the first context's description, for the summary line
};

// The progress line of a case that has just finished: "[3/17] name: pass (0.35 s)".
void printCaseFinished(std::ostream& out, std::size_t finished, std::size_t total, const CaseResult& result);

// Renders and compares every case (`update[i]`: case i's golden is to be rewritten; the render is
// kept in its result). Prints the parallelism line, then a progress line per case as it finishes.
// The first thread's context decides the backend of the others. When a case throws, no new case
// starts, the running ones finish, and the error of the earliest failing case in suite order is
// rethrown: the one a run of one case at a time reports.
CaseRun runCases(const CheckSuite& suite, const std::vector<Scene>& scenes, const std::vector<bool>& update,
                 const CaseRunOptions& options, std::ostream& out);

}  // namespace tstyles::cli
