// Datasets read once for a check run (check_datasets.h).
#include "check_datasets.h"

#include "commands.h"

namespace tstyles::cli {

void CheckDatasets::readAll(const std::vector<Scene>& scenes) {
    for (const Scene& scene : scenes) series(scene.dataset);
}

const Series& CheckDatasets::series(const std::filesystem::path& dataset) {
    const std::lock_guard lock(mutex_);
    auto found = read_.find(dataset);
    if (found == read_.end()) found = read_.emplace(dataset, openDataset({dataset}, DatasetOptions{})).first;
    return found->second;
}

}  // namespace tstyles::cli
