// The dataset table of the benchmark matrix (bench_datasets.h).
#include "bench_datasets.h"

#include <algorithm>

#include "tstyles/scene/temporal_compositors.h"

namespace tstyles::cli {

const std::vector<BenchDataset>& benchDatasets() {
    static const std::vector<BenchDataset> datasets = {
        {"superellipsoid", "super-ellipsoid, 10 x 64^3, partial overlap", "figure4-"},
        {"superellipsoid-aligned", "super-ellipsoid, 10 steps on one 256x128x64 grid, fully aligned", "figure4-"},
        {"hurricane", "synthetic hurricane, 10 x 125x125x25, fully overlapping", "", "figure5-focus-step5",
         "figure6-left-max-density-change"},
        {"sonar", "sonar, 10 pings x 25x20x1319 beams, partial overlap", "", "figure6-centre-index-tstf",
         "figure6-right-max-density-change"},
    };
    return datasets;
}

BenchDataset benchDatasetFor(const std::string& folder) {
    const auto& datasets = benchDatasets();
    const auto found =
        std::find_if(datasets.begin(), datasets.end(), [&](const BenchDataset& d) { return d.folder == folder; });
    return found != datasets.end() ? *found : BenchDataset{folder, folder, "figure4-"};
}

std::string benchSceneFor(const BenchDataset& dataset, TemporalCompositor compositor, bool styled) {
    // The bundled scene whose transfer functions suit what reads the compositor.
    const CompositorReads reads = compositorInfo(compositor).reads;
    if (!dataset.indexScene.empty())
        return reads == CompositorReads::GradientTstf ? dataset.changeScene : dataset.indexScene;
    const std::string prefix = dataset.scenePrefix + (styled ? "styled-" : "");
    switch (reads) {
        case CompositorReads::IndexTstf: return prefix + "temporal-mip";
        case CompositorReads::Composited: return prefix + "temporal-average";
        case CompositorReads::GradientTstf: return prefix + "max-density-change";
    }
    return prefix + "temporal-mip";
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

}  // namespace tstyles::cli
