// The worker pool of `tstyles check --jobs`: the calling thread and jobs - 1 more each own a
// CaseWorker (context, renderer, datasets) and take the next case from a shared counter.
#include "check_runner.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <exception>
#include <iomanip>
#include <mutex>
#include <ostream>
#include <thread>

#include "check_case.h"
#include "tstyles/core/errors.h"
#include "tstyles/gl/cpu_rasterizer.h"

namespace tstyles::cli {
namespace {

// The state the threads share; everything but the two atomics is guarded by mutex_.
class CaseQueue {
public:
    CaseQueue(const CheckSuite& suite, const std::vector<Scene>& scenes, const std::vector<bool>& update,
              std::ostream& out)
        : suite_(suite), scenes_(scenes), update_(update), out_(out), results_(suite.cases.size()),
          errors_(suite.cases.size()) {}

    // Checks cases on `worker` until none is left or one has failed.
    void drain(CaseWorker& worker) {
        while (!stopped_) {
            const std::size_t index = next_++;
            if (index >= suite_.cases.size()) return;
            try {
                finish(index, worker.check(suite_.cases[index], scenes_[index], update_[index]));
            } catch (...) {
                const std::lock_guard lock(mutex_);
                errors_[index] = std::current_exception();
                stopped_ = true;
                return;
            }
        }
    }

    // A thread that could not start working (no context, no thread): the run stops.
    void abandon(std::exception_ptr error) {
        const std::lock_guard lock(mutex_);
        if (!setupError_) setupError_ = error;
        stopped_ = true;
    }

    // Every result in suite order, or the error of the earliest failing case. Call after every
    // thread has ended.
    std::vector<CaseResult> results() {
        for (const std::exception_ptr& error : errors_)
            if (error) std::rethrow_exception(error);
        if (setupError_) std::rethrow_exception(setupError_);
        std::vector<CaseResult> results;
        for (std::optional<CaseResult>& result : results_) results.push_back(std::move(*result));
        return results;
    }

private:
    void finish(std::size_t index, CaseResult result) {
        const std::lock_guard lock(mutex_);
        printCaseFinished(out_, ++finished_, results_.size(), result);
        results_[index] = std::move(result);
    }

    const CheckSuite& suite_;
    const std::vector<Scene>& scenes_;
    const std::vector<bool>& update_;
    std::ostream& out_;
    std::atomic<std::size_t> next_ = 0;
    std::atomic<bool> stopped_ = false;
    std::mutex mutex_;
    std::size_t finished_ = 0;
    std::vector<std::optional<CaseResult>> results_;
    std::vector<std::exception_ptr> errors_;
    std::exception_ptr setupError_;
};

std::string casesAtOnce(int jobs) {
    return jobs == 1 ? std::string("1 case at a time") : std::to_string(jobs) + " parallel cases";
}

}  // namespace

std::optional<int> parseJobs(const std::string& text) {
    if (text == "auto") return std::nullopt;
    int jobs = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), jobs);
    if (error != std::errc() || end != text.data() + text.size() || jobs < 1)
        throwInputError("", "--jobs", "is \"" + text + "\"; expected a whole number of cases at once >= 1, or auto");
    return jobs;
}

Parallelism chooseParallelism(std::optional<int> requested, const std::string& glRenderer, std::size_t caseCount,
                              unsigned hardwareThreads) {
    const int cases = int(std::max<std::size_t>(caseCount, 1));
    if (requested) {
        const int jobs = std::min(*requested, cases);
        const std::string why = jobs < *requested ? " (--jobs " + std::to_string(*requested) + ", but the suite has " +
                                                        std::to_string(cases) + " cases)"
                                                  : " (--jobs " + std::to_string(jobs) + ")";
        return {jobs, casesAtOnce(jobs) + why};
    }
    if (const auto software = cpuRasterizerName(glRenderer))
        return {1, casesAtOnce(1) + ": " + std::string(*software) + " already uses every core (--jobs N overrides)"};
    const int jobs = std::min({4, int(std::max(hardwareThreads, 1u)), cases});
    return {jobs, casesAtOnce(jobs) + " (auto: at most 4, one per hardware thread" +
                      (jobs == cases && cases < 4 ? ", one per case)" : ")")};
}

void printCaseFinished(std::ostream& out, std::size_t finished, std::size_t total, const CaseResult& result) {
    out << "[" << finished << "/" << total << "] " << result.name << ": " << toString(result.outcome) << std::fixed
        << std::setprecision(2) << " (" << result.seconds << " s)\n"
        << std::defaultfloat << std::setprecision(6) << std::flush;
}

CaseRun runCases(const CheckSuite& suite, const std::vector<Scene>& scenes, const std::vector<bool>& update,
                 const CaseRunOptions& options, std::ostream& out) {
    // Every dataset is read before the first GL context and the other workers start (check_datasets.h).
    CheckDatasets datasets;
    datasets.readAll(scenes);
    CaseWorker first(options.backend, options.shaders, datasets);
    const std::string description = first.context().description();
    const GlBackend backend = first.context().backend();
    const Parallelism parallelism =
        chooseParallelism(options.jobs, description, suite.cases.size(), std::thread::hardware_concurrency());
    out << parallelism.line << "\n" << std::flush;
    CaseQueue queue(suite, scenes, update, out);
    {
        std::vector<std::jthread> helpers;  // joined at the end of this block
        try {
            for (int job = 1; job < parallelism.jobs; ++job) {
                helpers.emplace_back([&] {
                    try {
                        CaseWorker worker(backend, options.shaders, datasets);
                        queue.drain(worker);
                    } catch (...) {
                        queue.abandon(std::current_exception());
                    }
                });
            }
        } catch (...) {
            queue.abandon(std::current_exception());
        }
        queue.drain(first);
    }
    return {queue.results(), description};
}

}  // namespace tstyles::cli
