// The datasets of a `tstyles check` run, each read once and shared by the workers. Reading forks a
// reader process (docs/readers.md), and a fork while another thread holds a lock (an allocator's,
// while it renders) leaves the child waiting on it for good: seen under AddressSanitizer with
// --jobs 3, where the reader was ended after its deadline. So a run with several workers reads
// every dataset on the calling thread before any worker or GL context starts.
#pragma once

#include <filesystem>
#include <map>
#include <mutex>
#include <vector>

#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"

namespace tstyles::cli {

class CheckDatasets {
public:
    // Reads the dataset of every scene not read yet, in order.
    void readAll(const std::vector<Scene>& scenes);
    // The dataset's series; read now if it was not yet (one worker alone, as a process of
    // --distributed is). Thread-safe; the series stays where it is until this object goes.
    const Series& series(const std::filesystem::path& dataset);

private:
    std::mutex mutex_;
    std::map<std::filesystem::path, Series> read_;
};

}  // namespace tstyles::cli
