// Build-time tool: writes the paper's bouncing super-ellipsoid, the bundled default dataset
// (docs/superellipsoid-dataset.md). Usage:
//   generate_superellipsoid --output DIR [--aligned] [--steps N] [--resolution R] [--duration S]
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "generator_main.h"

#include "superellipsoid/bouncing_series.h"
#include "tstyles/data/manifest.h"

int main(int argc, char** argv) {
    CLI::App app{"Writes the bouncing super-ellipsoid time-series (uint8 densities)."};
    std::filesystem::path output;
    superellipsoid::BouncingSeriesOptions options;
    app.add_option("--output", output, "Directory for series.json and the raw files")->required();
    app.add_flag("--aligned", options.aligned,
                 "All time-steps on one common world grid instead of boxes riding with the object");
    app.add_option("--steps", options.steps, "Number of time-steps, uniform in time")
        ->check(CLI::Range(1, 100000));
    app.add_option("--resolution", options.resolution, "Samples along each axis of a box")
        ->check(CLI::Range(8, 1024));
    app.add_option("--duration", options.duration, "Simulated seconds the time-steps span")
        ->check(CLI::Range(0.01, 1000.0));
    if (const auto exitCode = generator::parseArguments(app, argc, argv)) return *exitCode;

    const int exitCode = generator::runReportingErrors(
        "generate_superellipsoid", [&] { tstyles::writeSeries(superellipsoid::buildBouncingSeries(options), output); });
    if (exitCode != 0) return exitCode;
    std::cout << "wrote " << options.steps << " time-steps to " << output.string() << "\n";
    return 0;
}
