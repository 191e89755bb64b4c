// Build-time tool: writes the synthetic sonar survey (docs/sonar-dataset.md): pings on beam grids
// from a moving vessel, a drifting fish school with a mask per ping, the seabed. Usage:
//   generate_sonar --output DIR [--pings N]
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "generator_main.h"

#include "sonar/sonar_series.h"

int main(int argc, char** argv) {
    CLI::App app{"Writes the synthetic sonar survey (uint16 echo amplitudes, one beam grid and school mask per ping)."};
    std::filesystem::path output;
    sonar::SonarSeriesOptions options;
    app.add_option("--output", output, "Directory for series.json and the raw files")->required();
    app.add_option("--pings", options.pings, "Number of pings (time-steps), 2 s apart")
        ->check(CLI::Range(1, sonar::kMaxPings));
    if (const auto exitCode = generator::parseArguments(app, argc, argv)) return *exitCode;

    const int exitCode = generator::runReportingErrors(
        "generate_sonar", [&] { tstyles::writeSeries(sonar::buildSonarSeries(options), output); });
    if (exitCode != 0) return exitCode;
    std::cout << "wrote " << options.pings << " pings to " << output.string() << "\n";
    return 0;
}
