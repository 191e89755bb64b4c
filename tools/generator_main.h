// What every generator in tools/ does the same way around its own work: --help is a success, a
// usage error exits 2 like bad input, and a failure while writing is reported with the tool's name
// and exits 2 (never a crash).
#pragma once

#include <exception>
#include <functional>
#include <iostream>
#include <optional>
#include <string_view>

#include <CLI/CLI.hpp>

namespace generator {

// Parses the command line. Returns the exit code to stop with (0 after --help, 2 for a usage
// error), or nothing when the generator should go on.
inline std::optional<int> parseArguments(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? 0 : 2;
    }
    return std::nullopt;
}

// Runs `write`; an exception (bad input, a folder that cannot be written, a series the writer
// refuses) is reported as "tool: message" and gives exit code 2. Otherwise returns 0.
inline int runReportingErrors(std::string_view tool, const std::function<void()>& write) {
    try {
        write();
    } catch (const std::exception& error) {
        std::cerr << tool << ": " << error.what() << "\n";
        return 2;
    }
    return 0;
}

}  // namespace generator
