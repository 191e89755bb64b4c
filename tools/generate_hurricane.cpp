// Build-time tool: writes the synthetic hurricane, a bundled dataset with missing values (land)
// and an uneven vertical axis (docs/hurricane-dataset.md). Usage:
//   generate_hurricane --output DIR [--steps N]
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "hurricane/hurricane_series.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/manifest.h"

int main(int argc, char** argv) {
    CLI::App app{"Writes the synthetic hurricane time-series (uint8 cloud water, land missing)."};
    std::filesystem::path output;
    hurricane::HurricaneSeriesOptions options;
    app.add_option("--output", output, "Directory for series.json and the raw files")->required();
    app.add_option("--steps", options.steps, "Number of time-steps, uniform over 48 hours")
        ->check(CLI::Range(1, 1000));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? 0 : 2;
    }
    try {
        tstyles::writeSeries(hurricane::buildHurricaneSeries(options), output);
    } catch (const tstyles::InputError& error) {
        std::cerr << "generate_hurricane: " << error.what() << "\n";
        return 2;
    } catch (const std::exception& error) {  // a series the writer refuses: say so, never a crash
        std::cerr << "generate_hurricane: " << error.what() << "\n";
        return 2;
    }
    std::cout << "wrote " << options.steps << " time-steps to " << output.string() << "\n";
    return 0;
}
