// Build-time tool: writes the paper's bouncing super-ellipsoid, the bundled default dataset
// (docs/superellipsoid-dataset.md). Usage:
//   generate_superellipsoid --output DIR [--aligned] [--steps N] [--resolution R] [--duration S]
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "superellipsoid/bouncing_series.h"
#include "tstyles/core/errors.h"
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
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // Help is a success; any other parse problem is a usage error: exit 2, like user errors.
        const int code = app.exit(error);
        return code == 0 ? 0 : 2;
    }

    try {
        tstyles::writeSeries(superellipsoid::buildBouncingSeries(options), output);
    } catch (const tstyles::InputError& error) {
        std::cerr << "generate_superellipsoid: " << error.what() << "\n";
        return 2;
    }
    std::cout << "wrote " << options.steps << " time-steps to " << output.string() << "\n";
    return 0;
}
