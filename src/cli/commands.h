// The subcommands of `tstyles`. Each registers its options on the CLI11 app and runs when chosen.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "tstyles/core/bundled_data.h"
#include "tstyles/gl/headless_context.h"

namespace tstyles::cli {

// Exit codes: 0 success, 2 bad input, 3 no usable OpenGL, 1 anything else.
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitNoOpenGl = 3;

// Options every GL-using command shares.
struct GlOptions {
    std::string backend = "auto";
    std::optional<std::filesystem::path> shaderDirectory;
};
void addGlOptions(CLI::App& command, GlOptions& options);
GlBackend parseBackend(const std::string& name);

struct Command {
    CLI::App* parsed = nullptr;     // the subcommand, to see whether it was chosen
    std::function<int()> run;       // runs it with the parsed options; returns the exit code
};

Command addRenderCommand(CLI::App& app);
Command addInfoCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);

}  // namespace tstyles::cli
