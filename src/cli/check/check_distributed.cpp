// The rounds of `tstyles check --distributed` (check_distributed.h): render this process's case of
// the round, agree that every process did, then send the results to process 0.
#include "check_distributed.h"

#include <algorithm>
#include <cstdint>
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
    const std::string spread = processes == 1 ? " MPI process, one at a time" : " MPI processes, one at a time each";
    return std::to_string(cases) + " cases over " + count + spread + " (--distributed: case k on process (k-1) mod " +
           count + ")";
}

}  // namespace

CaseRun runCasesDistributed(const MpiSession& mpi, const CheckSuite& suite, const std::vector<Scene>& scenes,
                            const std::vector<bool>& update, const CaseRunOptions& options, std::ostream& out) {
    const std::size_t total = suite.cases.size();
    const std::size_t processes = std::size_t(mpi.processCount());
    CheckDatasets datasets;  // one worker per process, which reads each dataset as its cases need it
    std::optional<CaseWorker> worker;
    mpi.together("starting OpenGL", [&] {
        // A process beyond the last case has nothing to render and makes no context.
        if (std::size_t(mpi.rank()) < total) worker.emplace(options.backend, options.shaders, datasets);
    });
    if (mpi.isFirst()) out << spreadLine(mpi.processCount(), total) << "\n" << std::flush;

    CaseRun run{{}, worker ? worker->context().description() : std::string()};
    for (std::size_t round = 0; round * processes < total; ++round) {
        const std::size_t first = round * processes, end = std::min(total, first + processes);
        const std::size_t mine = first + std::size_t(mpi.rank());
        std::optional<CaseResult> result;
        std::vector<std::uint8_t> message;  // the result as sent to process 0
        mpi.together("rendering the cases", [&] {
            if (mine >= total) return;
            result = checkNamingTheCase(*worker, suite.cases[mine], scenes[mine], update[mine]);
            if (!mpi.isFirst()) message = encodeCaseResult(*result);
        });
        // What can fail here (reading a message) runs inside `together` too, after every message
        // of the round has been received: a process never waits on one that has given up.
        mpi.together("gathering the results", [&] {
            if (!mpi.isFirst()) {
                if (mine < total) mpi.send(0, message);
                return;
            }
            std::vector<std::vector<std::uint8_t>> received(end - first);
            for (std::size_t index = first + 1; index < end; ++index)
                received[index - first] = mpi.receive(int(index - first));
            for (std::size_t index = first; index < end; ++index) {
                run.results.push_back(index == first ? std::move(*result) : decodeCaseResult(received[index - first]));
                printCaseFinished(out, index + 1, total, run.results.back());
            }
        });
    }
    return run;
}

}  // namespace tstyles::cli
