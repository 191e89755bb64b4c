// Options and lookups shared by the subcommands.
#include <cstdlib>
#include <filesystem>
#include <new>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/isolated_reading.h"

namespace tstyles::cli {

void addGlOptions(CLI::App& command, GlOptions& options) {
    command.add_option("--backend", options.backend, "Headless OpenGL: auto (EGL, then OSMesa), egl, osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    addShaderDirectoryOption(command, options.shaderDirectory);
}

void addShaderDirectoryOption(CLI::App& command, std::optional<std::filesystem::path>& directory) {
    command.add_option("--shader-dir", directory,
                       "Load shaders from this folder instead of the embedded copy (also: TSTYLES_SHADER_DIR)")
        ->check(CLI::ExistingDirectory);
}

void addImageSizeOptions(CLI::App& command, const std::string& what, std::optional<int>& width,
                         std::optional<int>& height) {
    command.add_option("--width", width, what + " width (overrides the scene)")->check(CLI::Range(1, 16384));
    command.add_option("--height", height, what + " height (overrides the scene)")->check(CLI::Range(1, 16384));
}

GlBackend parseBackend(const std::string& name) {
    auto backend = glBackendFromString(name);
    if (!backend) throwInputError("", "--backend", "unknown backend \"" + name + "\"");
    return *backend;
}

void addDatasetOptions(CLI::App& command, DatasetOptions& options) {
    for (const ReaderOptionLine& line : readerOptionLines()) {
        const std::string key(line.key);
        const std::string name(line.cli);
        const std::string help(line.help);
        switch (line.kind) {
            case ReaderOptionKind::Flag:
                command.add_flag_callback(name, [&options, key] { options.texts[key] = {"true"}; }, help);
                break;
            case ReaderOptionKind::Files:
                command
                    .add_option_function<std::vector<std::string>>(
                        name, [&options, key](const std::vector<std::string>& values) { options.texts[key] = values; },
                        help)
                    ->delimiter(',')
                    ->type_name(std::string(line.valueName));
                break;
            default:
                command
                    .add_option_function<std::string>(
                        name, [&options, key](const std::string& value) { options.texts[key] = {value}; }, help)
                    ->type_name(std::string(line.valueName));
        }
    }
}

ReadOptions toReadOptions(const DatasetOptions& options) { return readOptionsFrom(options.texts); }

Series openDataset(const std::vector<std::filesystem::path>& inputs, const DatasetOptions& options) {
    const ReadOptions read = toReadOptions(options);
    // The readers check sizes against the files and the memory cap; these are the backstops for a
    // size that got past them, said as the input problem they are.
    try {
        return openSeriesIsolated(inputs, read);
    } catch (const std::bad_alloc&) {
        throwInputError(inputs.front(), "",
                        "not enough memory to read it (the sizes it declares are too large for this machine; "
                        "--max-memory or --steps can ask for less)");
    } catch (const std::filesystem::filesystem_error& error) {
        throwInputError(error.path1().empty() ? inputs.front() : error.path1(), "",
                        "cannot be read: " + error.code().message());
    }
}

}  // namespace tstyles::cli
