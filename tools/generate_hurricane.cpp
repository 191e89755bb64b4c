// Build-time tool: writes the synthetic hurricane, a bundled dataset with missing values (land)
// and an uneven vertical axis (docs/hurricane-dataset.md). Usage:
//   generate_hurricane --output DIR [--steps N]
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "generator_main.h"

#include "hurricane/hurricane_series.h"
#include "tstyles/data/manifest.h"

int main(int argc, char** argv) {
    CLI::App app{"Writes the synthetic hurricane time-series (uint8 cloud water, land missing)."};
    std::filesystem::path output;
    hurricane::HurricaneSeriesOptions options;
    app.add_option("--output", output, "Directory for series.json and the raw files")->required();
    app.add_option("--steps", options.steps, "Number of time-steps, uniform over 48 hours")
        ->check(CLI::Range(1, 1000));
    if (const auto exitCode = generator::parseArguments(app, argc, argv)) return *exitCode;
    const int exitCode = generator::runReportingErrors(
        "generate_hurricane", [&] { tstyles::writeSeries(hurricane::buildHurricaneSeries(options), output); });
    if (exitCode != 0) return exitCode;
    std::cout << "wrote " << options.steps << " time-steps to " << output.string() << "\n";
    return 0;
}
