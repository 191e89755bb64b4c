// `tstyles info DATASET`: what a series holds, where its time-steps sit, how they overlap.
#include <iostream>
#include <memory>

#include "commands.h"
#include "tstyles/data/manifest.h"
#include "tstyles/data/series_summary.h"

namespace tstyles::cli {

Command addInfoCommand(CLI::App& app) {
    auto dataset = std::make_shared<std::filesystem::path>();
    CLI::App* command = app.add_subcommand("info", "Describe a dataset: time-steps, grids, placements, overlap, memory");
    command->add_option("dataset", *dataset, "Dataset manifest (series.json)")->required();
    return {command, [dataset] {
                std::cout << describeSeries(loadSeries(*dataset));
                return kExitSuccess;
            }};
}

}  // namespace tstyles::cli
