// `tstyles convert INPUT... -o FOLDER`: a scientist's file (any format of docs/readers.md),
// read with the usual options, kept as our manifest form (docs/dataset-format.md).
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/data/series_export.h"
#include "tstyles/data/isolated_reading.h"
#include "tstyles/data/format_listing.h"

namespace tstyles::cli {
namespace {

struct ConvertOptions {
    std::vector<std::filesystem::path> inputs;
    std::filesystem::path output;
    bool force = false;
    DatasetOptions dataset;
};

int runConvert(const ConvertOptions& options) {
    // Before any reading: a name the system refuses, or a file (or FIFO) where the folder would go.
    const PathKind outputKind = userPathKind({"", "-o"}, options.output);
    if (outputKind == PathKind::RegularFile || outputKind == PathKind::Other)
        throwInputError(options.output, "-o", "exists and is not a folder: the output of convert is a dataset folder");
    const Series raw = openRawSeriesIsolated(options.inputs, toReadOptions(options.dataset));
    writeSeriesFolder(toRawSeries(raw, options.inputs.front()), options.output, options.force);
    std::size_t voxels = 0;
    for (const TimeStep& step : raw.steps) voxels += step.density.size();
    std::cout << "wrote " << (options.output / "series.json").string() << " (" << raw.sourceFormat << ", "
              << raw.size() << " time-steps, " << voxels << " float32 values, value range [" << raw.valueRange[0]
              << ", " << raw.valueRange[1] << "])\n";
    return kExitSuccess;
}

}  // namespace

Command addConvertCommand(CLI::App& app) {
    auto options = std::make_shared<ConvertOptions>();
    CLI::App* command = app.add_subcommand(
        "convert", "Read a scientist's files (" + seriesFormatNames() + ") and keep the series as a tstyles manifest folder");
    command
        ->add_option("input", options->inputs,
                     std::string("The dataset: ") + datasetKindsText())
        ->required();
    command->add_option("-o,--output", options->output, "Dataset folder to write (series.json and raw files)")
        ->required();
    command->add_flag("--force", options->force, "Replace the output folder if it exists and is not empty");
    addDatasetOptions(*command, options->dataset);
    return {command, [options] { return runConvert(*options); }};
}

}  // namespace tstyles::cli
