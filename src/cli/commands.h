// The subcommands of `tstyles`. Each registers its options on the CLI11 app and runs when chosen.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cli11_forward.h"

#include "tstyles/core/bundled_data.h"
#include "tstyles/data/read_options.h"
#include "tstyles/data/reader_option_table.h"
#include "tstyles/data/series.h"
#include "tstyles/gl/headless_context.h"

namespace tstyles::cli {

// Exit codes: 0 success, 2 bad input, 3 no usable OpenGL, 130 interrupted, 1 anything else.
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitNoOpenGl = 3;
// Ctrl+C, as shells report a process ended by SIGINT (128 + 2).
inline constexpr int kExitInterrupted = 130;

// Options every GL-using command shares.
struct GlOptions {
    std::string backend = "auto";
    std::optional<std::filesystem::path> shaderDirectory;
};
void addGlOptions(CLI::App& command, GlOptions& options);
// --shader-dir alone, for a command with a window (view).
void addShaderDirectoryOption(CLI::App& command, std::optional<std::filesystem::path>& directory);
// --width and --height, overriding the scene's, of an image (`what` "Image") or a movie's frames.
void addImageSizeOptions(CLI::App& command, const std::string& what, std::optional<int>& width,
                         std::optional<int>& height);
GlBackend parseBackend(const std::string& name);

// How a dataset is read (docs/readers.md): the reader options as typed, per key of the reader
// options' table (reader_option_table.h), which registers them on the command line; toReadOptions
// checks and converts them when the command runs, so that a bad one is an InputError naming the
// option. Shared by info, render, view, scene, animate, convert and bench.
struct DatasetOptions {
    ReaderOptionTexts texts;
};
void addDatasetOptions(CLI::App& command, DatasetOptions& options);
ReadOptions toReadOptions(const DatasetOptions& options);
// The one way a command opens a dataset: openSeries with the parsed options, in a reader process
// (isolated_reading.h).
Series openDataset(const std::vector<std::filesystem::path>& inputs, const DatasetOptions& options);

struct Command {
    CLI::App* parsed = nullptr;     // the subcommand, to see whether it was chosen
    std::function<int()> run;       // runs it with the parsed options; returns the exit code
};

Command addRenderCommand(CLI::App& app);
Command addInfoCommand(CLI::App& app);
Command addProbeCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);
Command addConvertCommand(CLI::App& app);
Command addSceneCommand(CLI::App& app);
Command addAnimateCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addCheckCommand(CLI::App& app);

}  // namespace tstyles::cli
