// Manifest or Plot3D: which reader a dataset path goes to, by extension or by content.
#include "dataset_loading.h"

#include <cctype>
#include <fstream>
#include <system_error>

#include "tstyles/core/errors.h"
#include "tstyles/data/manifest.h"

namespace tstyles::cli {

void addPlot3DOptions(CLI::App& command, Plot3DCliOptions& options) {
    command.add_option("--solution", options.solutions,
                       "Plot3D: solution (.q) or function (.f) files, one per time-step in time order "
                       "(comma-separated or repeated)")
        ->delimiter(',');
    command.add_option("--var", options.variable,
                       "Plot3D: the quantity shown as density: density, x-momentum, y-momentum, z-momentum, energy, "
                       "momentum-magnitude, pressure; function-K for function (.f) files");
    command.add_option("--block", options.block, "Plot3D: which block of a multi-block file (from 0)")
        ->check(CLI::NonNegativeNumber);
    command.add_option("--gamma", options.gamma, "Plot3D: ratio of specific heats, for pressure")
        ->check(CLI::Range(1.0000001, 10.0));
}

namespace {

// A file that does not start like a JSON manifest (an object, perhaps after a comment) is taken for
// a Plot3D grid, whose reader then says clearly if it is not one either.
bool looksLikeBinaryGrid(const std::filesystem::path& dataset) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(dataset, error) || dataset.extension() == ".json") return false;
    std::ifstream in(dataset, std::ios::binary);
    char first = 0;
    while (in.get(first) && std::isspace(static_cast<unsigned char>(first))) {
    }
    return in && first != '{' && first != '/';
}

}  // namespace

Series loadDataset(const std::filesystem::path& dataset, const Plot3DCliOptions& plot3d) {
    if (hasPlot3DGridExtension(dataset) || !plot3d.solutions.empty() || looksLikeBinaryGrid(dataset)) {
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
