// Build-time tool: writes the synthetic sonar survey (docs/sonar-dataset.md): pings on beam grids
// from a moving vessel, a drifting fish school with a mask per ping, the seabed. Usage:
//   generate_sonar --output DIR [--pings N]
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "sonar/sonar_series.h"
#include "tstyles/core/errors.h"

int main(int argc, char** argv) {
    CLI::App app{"Writes the synthetic sonar survey (uint16 echo amplitudes, one beam grid and school mask per ping)."};
    std::filesystem::path output;
    sonar::SonarSeriesOptions options;
    app.add_option("--output", output, "Directory for series.json and the raw files")->required();
    app.add_option("--pings", options.pings, "Number of pings (time-steps), 2 s apart")
        ->check(CLI::Range(1, sonar::kMaxPings));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? 0 : 2;
    }

    try {
        tstyles::writeSeries(sonar::buildSonarSeries(options), output);
    } catch (const tstyles::InputError& error) {
        std::cerr << "generate_sonar: " << error.what() << "\n";
        return 2;
    }
    std::cout << "wrote " << options.pings << " pings to " << output.string() << "\n";
    return 0;
}
