// `tstyles info DATASET...`: what a series holds, where its time-steps sit, how they overlap.
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "gpu_memory_option.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/data/series_summary.h"
#include "tstyles/data/format_listing.h"

namespace tstyles::cli {

Command addInfoCommand(CLI::App& app) {
    auto inputs = std::make_shared<std::vector<std::filesystem::path>>();
    auto dataset = std::make_shared<DatasetOptions>();
    auto gpuMemory = std::make_shared<GpuMemoryOption>();
    CLI::App* command = app.add_subcommand("info", "Describe a dataset: time-steps, grids, placements, overlap, memory");
    command
        ->add_option("dataset", *inputs,
                     std::string("Dataset: ") + datasetKindsText())
        ->required();
    addDatasetOptions(*command, *dataset);
    addGpuMemoryOption(*command, *gpuMemory);
    return {command, [inputs, dataset, gpuMemory] {
                parseGpuMemoryOption(*gpuMemory);
                const Series series = openDataset(*inputs, *dataset);
                std::cout << describeSeries(series);
                describeGpuMemory(std::cout, series, *gpuMemory);
                std::cout << "\nautomatic scene (tstyles render/view/scene of this dataset; docs/automatic-scene.md):\n";
                for (const std::string& line : automaticScene(series, inputs->front()).explanation)
                    std::cout << "  " << line << "\n";
                return kExitSuccess;
            }};
}

}  // namespace tstyles::cli
