// The rounds of `tstyles check --distributed` (check_distributed.h): render this process's case of
// the round, agree that every process did, then send the results to process 0.
#include "check_distributed.h"

#include <mutex>
#include <new>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "check_case.h"
#include "check_result_message.h"
#include "tstyles/core/errors.h"

namespace tstyles::cli {
namespace {

// Checks a case, naming it in any error: process 0 reports errors of every process, and "case X"
// says which of the suite's cases could not be rendered. The error keeps its kind (and exit code).
CaseResult checkNamingTheCase(CaseWorker& worker, const CheckCase& entry, const Scene& scene, bool update) {
    const std::string which = "case \"" + entry.name + "\" (" + entry.scene.string() + "): ";
    try {
        return worker.check(entry, scene, update);
    } catch (const InputError& error) {
        throw InputError(which + error.what());
    } catch (const GlUnavailableError& error) {
        throw GlUnavailableError(which + error.what());
    } catch (const std::bad_alloc&) {
        throw InputError(which + "not enough memory to render it on this process");
    } catch (const std::exception& error) {
        throw std::runtime_error(which + error.what());
    }
}

std::string spreadLine(int processes, std::size_t cases) {
    const std::string count = std::to_string(processes);
    return std::to_string(cases) + " cases over " + count + " MPI process" + (processes == 1 ? "" : "es") +
           ", one at a time each (--distributed: case k on process (k-1) mod " + count + ")";
}

}  // namespace

CaseRun runCasesDistributed(const MpiSession& mpi, const CheckSuite& suite, const std::vector<Scene>& scenes,
                            const std::vector<bool>& update, const CaseRunOptions& options, std::ostream& out) {
    std::mutex datasetReading;  // one worker per process: never contended
    std::optional<CaseWorker> worker;
    mpi.together("starting OpenGL", [&] { worker.emplace(options.backend, options.shaders, datasetReading); });
    const std::size_t total = suite.cases.size();
    const std::size_t processes = std::size_t(mpi.processCount());
    if (mpi.isFirst()) out << spreadLine(mpi.processCount(), total) << "\n" << std::flush;

    CaseRun run{{}, worker->context().description()};
    for (std::size_t round = 0; round * processes < total; ++round) {
        const std::size_t mine = round * processes + std::size_t(mpi.rank());
        std::optional<CaseResult> result;
        mpi.together("rendering the cases", [&] {
            if (mine < total) result = checkNamingTheCase(*worker, suite.cases[mine], scenes[mine], update[mine]);
        });
        if (!mpi.isFirst()) {
            if (result) mpi.send(0, encodeCaseResult(*result));
            continue;
        }
        // Process 0 takes the round's results in suite order: its own, then one from each process.
        for (std::size_t index = round * processes; index < std::min(total, (round + 1) * processes); ++index) {
            const int from = int(index % processes);
            run.results.push_back(from == 0 ? std::move(*result) : decodeCaseResult(mpi.receive(from)));
            printCaseFinished(out, index + 1, total, run.results.back());
        }
    }
    return run;
}

}  // namespace tstyles::cli
