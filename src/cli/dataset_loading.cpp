// Manifest or Plot3D: which reader a dataset path goes to.
#include "dataset_loading.h"

#include "tstyles/core/errors.h"
#include "tstyles/data/manifest.h"

namespace tstyles::cli {

void addPlot3DOptions(CLI::App& command, Plot3DCliOptions& options) {
    command.add_option("--solution", options.solutions,
                       "Plot3D: solution (q) files, one per time-step in time order (comma-separated or repeated)")
        ->delimiter(',');
    command.add_option("--var", options.variable, "Plot3D: the quantity shown as density")
        ->check(CLI::IsMember(plot3DVariableNames()));
    command.add_option("--block", options.block, "Plot3D: which block of a multi-block file (from 0)")
        ->check(CLI::NonNegativeNumber);
    command.add_option("--gamma", options.gamma, "Plot3D: ratio of specific heats, for pressure")
        ->check(CLI::Range(1.0000001, 10.0));
}

Series loadDataset(const std::filesystem::path& dataset, const Plot3DCliOptions& plot3d) {
    if (hasPlot3DGridExtension(dataset) || !plot3d.solutions.empty()) {
        Plot3DOptions options;
        options.gridFile = dataset;
        options.solutionFiles = plot3d.solutions;
        options.variable = plot3d.variable;
        options.block = plot3d.block;
        options.gamma = plot3d.gamma;
        return readPlot3D(options);
    }
    return loadSeries(dataset);
}

}  // namespace tstyles::cli
