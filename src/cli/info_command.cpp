// `tstyles info DATASET`: what a series holds, where its time-steps sit, how they overlap.
#include <iostream>
#include <memory>

#include "commands.h"
#include "dataset_loading.h"
#include "tstyles/data/manifest.h"
#include "tstyles/data/series_summary.h"

namespace tstyles::cli {

Command addInfoCommand(CLI::App& app) {
    auto dataset = std::make_shared<std::filesystem::path>();
    auto plot3d = std::make_shared<Plot3DCliOptions>();
    CLI::App* command = app.add_subcommand("info", "Describe a dataset: time-steps, grids, placements, overlap, memory");
    command->add_option("dataset", *dataset, "Dataset manifest (series.json), or a Plot3D grid file")->required();
    addPlot3DOptions(*command, *plot3d);
    return {command, [dataset, plot3d] {
                std::cout << describeSeries(loadDataset(*dataset, *plot3d));
                return kExitSuccess;
            }};
}

}  // namespace tstyles::cli
