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
    command.add_option("--var", options.variable,
                       "NetCDF: the variable to read; Plot3D: density, x-momentum, y-momentum, z-momentum, energy, "
                       "momentum-magnitude, pressure, or function-K for function (.f) files");
    command.add_option("--time-dim", options.timeDimension, "NetCDF: the time dimension, when it is not found");
    command.add_flag("--index-axes", options.indexAxes, "NetCDF: unit spacing instead of the coordinate variables");
    command.add_option("--steps", options.steps,
                       "Time-steps FIRST:END:STRIDE (END exclusive, may be empty), e.g. 0:48:5");
    command.add_option("--range", options.range, "Raw values LO:HI map to density 0 and 1 (default: the data's)");
    command.add_option("--resample", options.resample, "Resample every time-step to NXxNYxNZ (rectilinear grids)");
    command.add_option("--dims", options.rawDims,
                       "Hurricane Isabel raw files: samples per file NXxNYxNZ (default 500x500x100); plain TIFF: "
                       "the samples of one volume");
    command.add_option("--channel", options.channel, "TIFF, OME-Zarr: which channel of a multi-channel image (from 0)")
        ->check(CLI::NonNegativeNumber);
    command.add_option("--series", options.series,
                       "DICOM: which series of the folder, by its instance UID or its number in `tstyles info` "
                       "(default: the largest)");
    command.add_option("--axes", options.axes,
                       "Plain TIFF: what the pages are, slowest axis first: TZYX (default) or ZTYX");
    command.add_option("--level", options.level, "OME-Zarr: the resolution level, 0 the finest (default: the "
                       "finest that fits the memory limits)")
        ->check(CLI::NonNegativeNumber);
    command.add_option("--precision", options.precision, "Bits per density on the GPU: 8, 16 (default) or 32");
    command.add_option("--max-memory", options.maxMemory,
                       "Memory the series may take (host + GPU copy), e.g. 512M, 2G; more is refused or fitted");
    command.add_option("--fit", options.fit,
                       "With --max-memory, a series too large is: refuse (default), resolution (read smaller), "
                       "steps (fewer time-steps)");
    command.add_option("--solution", options.solutions,
                       "Plot3D: solution (.q) or function (.f) files, one per time-step in time order "
                       "(comma-separated or repeated); the dataset is then the grid file")
        ->delimiter(',');
    command.add_option("--block", options.block, "Plot3D: which block of a multi-block file (from 0)")
        ->check(CLI::NonNegativeNumber);
    command.add_option("--gamma", options.gamma, "Plot3D: ratio of specific heats, for pressure")
        ->check(CLI::Range(1.0000001, 10.0));
}

ReadOptions toReadOptions(const DatasetOptions& options) {
    ReadOptions read;
    read.variable = options.variable;
    read.timeDimension = options.timeDimension;
    read.indexAxes = options.indexAxes;
    if (options.steps) read.steps = parseStepSelection(*options.steps, "--steps");
    if (options.range) read.valueRange = parseValueRange(*options.range, "--range");
    if (options.resample) read.resampleTo = parseDims(*options.resample, "--resample");
    if (options.rawDims) read.rawDims = parseDims(*options.rawDims, "--dims");
    read.channel = options.channel;
    read.seriesChoice = options.series;
    read.pageAxes = options.axes;
    read.level = options.level;
    if (options.precision) read.precision = parseDensityPrecision(*options.precision, "--precision");
    if (options.maxMemory) read.maxMemoryBytes = parseMemorySize(*options.maxMemory, "--max-memory");
    if (options.fit) {
        if (!options.maxMemory) throwInputError("", "--fit", "says what to do over --max-memory, which is not given");
        read.fit = parseMemoryFit(*options.fit, "--fit");
    }
    read.solutionFiles = options.solutions;
    read.block = options.block;
    read.gamma = options.gamma;
    return read;
}

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
