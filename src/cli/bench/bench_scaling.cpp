// Longer bouncing super-ellipsoid series for `tstyles bench --scaling` (bench_scaling.h).
#include "bench_scaling.h"

#include <filesystem>
#include <system_error>

#include <unistd.h>

#include "superellipsoid/bouncing_series.h"
#include "tstyles/data/manifest.h"

namespace tstyles::cli {
namespace {

// A folder under the system's temporary directory that is removed with everything in it.
class ScratchFolder {
public:
    explicit ScratchFolder(const std::string& name)
        : path_(std::filesystem::temp_directory_path() /
                ("tstyles-" + name + "-" + std::to_string(::getpid()))) {
        std::filesystem::create_directories(path_);
    }
    ~ScratchFolder() {
        std::error_code ignored;  // a folder left behind in /tmp is no reason to fail the run
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

double bundledDuration() { return superellipsoid::BouncingSeriesOptions{}.duration; }

}  // namespace

double scalingDuration(int steps) {
    const superellipsoid::BouncingSeriesOptions bundled;
    return bundled.duration * double(steps - 1) / double(bundled.steps - 1);
}

std::string scalingDatasetName(int steps, bool aligned) {
    return std::string(aligned ? "superellipsoid-aligned" : "superellipsoid") + "-x" + std::to_string(steps);
}

Series buildScalingSeries(int steps, bool aligned) {
    superellipsoid::BouncingSeriesOptions options;
    options.steps = steps;
    options.aligned = aligned;
    // Partial overlap: a longer simulation, boxes riding with the object. Full overlap: the bundled
    // 1.6 s on the same 256x128x64 common grid, sampled more densely in time; a longer path would
    // make that grid coarser (it is capped), down to a few voxels across the object.
    options.duration = aligned ? bundledDuration() : scalingDuration(steps);
    const ScratchFolder folder(scalingDatasetName(steps, aligned));
    writeSeries(superellipsoid::buildBouncingSeries(options), folder.path());
    return loadSeries(folder.path() / "series.json");
}

}  // namespace tstyles::cli
