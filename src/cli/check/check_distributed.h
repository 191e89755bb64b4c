// `tstyles check --distributed`: the cases of a suite spread over the processes of an MPI run,
// process r taking cases r, r + N, r + 2N, ... whole (each renders its case alone: no sort-last),
// and every result gathered on process 0 in suite order.
#pragma once

#include <iosfwd>
#include <vector>

#include "check_runner.h"
#include "tstyles/distributed/mpi_session.h"

namespace tstyles::cli {

// Collective. Each process with a case makes one CaseWorker and renders its cases one at a time,
// in rounds of one case per process; after each round the processes agree (MpiSession::together)
// whether any case failed to render, so a failure ends every process within one round, reported
// by process 0 with the case named, and again once process 0 has every result of the round. Process 0 prints a line saying how the cases are spread, a progress line
// per case in suite order, and returns every result in suite order; the others return no results.
// `options.jobs` is not used: one case at a time per process.
CaseRun runCasesDistributed(const MpiSession& mpi, const CheckSuite& suite, const std::vector<Scene>& scenes,
                            const std::vector<bool>& update, const CaseRunOptions& options, std::ostream& out);

}  // namespace tstyles::cli
