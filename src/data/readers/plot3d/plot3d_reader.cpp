// Plot3D grid + solution files to a series: one structured grid (the chosen block), one time-step
// per solution file, its density one solution variable or a quantity derived from them.
#include "tstyles/core/ascii_case.h"
#include "tstyles/data/plot3d.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include "plot3d_layout.h"
#include "plot3d_source.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

std::string nodeText(glm::ivec3 dims, std::size_t index) {
    const std::size_t x = index % std::size_t(dims.x);
    const std::size_t y = (index / std::size_t(dims.x)) % std::size_t(dims.y);
    const std::size_t z = index / (std::size_t(dims.x) * std::size_t(dims.y));
    return "(" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + ")";
}

std::string dimsText(glm::ivec3 dims) {
    return std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
}

// "function-K": variable K (from 0) of a function file.
std::optional<int> functionIndex(const std::string& variable) {
    const std::string prefix = "function-";
    if (variable.rfind(prefix, 0) != 0 || variable.size() == prefix.size() || variable.size() > prefix.size() + 4)
        return std::nullopt;
    int index = 0;
    for (char digit : variable.substr(prefix.size())) {
        if (!std::isdigit(static_cast<unsigned char>(digit))) return std::nullopt;
        index = index * 10 + (digit - '0');
    }
    return index;
}

bool hasFunctionExtension(const std::filesystem::path& path) {
    const std::string extension = lowercaseExtension(path);
    return extension == ".f" || extension == ".fun";
}

void requireBlock(const Plot3DFile& file, int block) {
    const int blocks = int(file.layout.dims.size());
    if (block < 0 || block >= blocks)
        throwInputError(file.path, "", "has " + std::to_string(blocks) + " block(s); block " + std::to_string(block) +
                                           " was asked for (--block counts from 0)");
}

struct GridBlock {
    StructuredGrid grid;
    std::vector<bool> blanked;  // IBLANK 0
};

GridBlock readGridBlock(const Plot3DFile& file, int block) {
    requireBlock(file, block);
    const glm::ivec3 dims = file.layout.dims[std::size_t(block)];
    if (glm::any(glm::lessThan(dims, glm::ivec3(2))))
        throwInputError(file.path, "", "block " + std::to_string(block) + " is " + dimsText(dims) +
                                           " nodes: a grid needs at least 2 nodes along each axis to have cells");
    const std::size_t nodes = std::size_t(dims.x) * dims.y * dims.z;
    const std::size_t precision = std::size_t(file.layout.precision);
    const std::size_t start = file.layout.blockOffsets[std::size_t(block)];
    std::vector<glm::vec3> positions(nodes);
    for (int axis = 0; axis < 3; ++axis)
        for (std::size_t node = 0; node < nodes; ++node) {
            const double value = file.real(start + (std::size_t(axis) * nodes + node) * precision);
            if (!std::isfinite(value))
                throwInputError(file.path, "", std::string("non-finite ") + "xyz"[axis] + " coordinate at node " +
                                                   nodeText(dims, node) + " of block " + std::to_string(block));
            positions[node][axis] = float(value);
        }
    GridBlock result{makeStructuredGrid(dims, std::move(positions), file.path), std::vector<bool>(nodes, false)};
    if (file.layout.iblank) {
        const std::size_t iblankStart = start + 3 * nodes * precision;
        for (std::size_t node = 0; node < nodes; ++node)
            result.blanked[node] = file.integer(iblankStart + node * 4) == 0;
    }
    if (const auto problem = findGridProblem(result.grid))
        throwInputError(file.path, "", "block " + std::to_string(block) + ": " + *problem);
    return result;
}

void requireMatchingDims(const Plot3DFile& file, int block, const GridBlock& grid,
                         const std::filesystem::path& gridFile) {
    const glm::ivec3 dims = file.layout.dims[std::size_t(block)];
    if (dims != grid.grid.dims)
        throwInputError(file.path, "", "block " + std::to_string(block) + " has " + dimsText(dims) +
                                           " nodes but the grid '" + gridFile.string() + "' has " +
                                           dimsText(grid.grid.dims) + " in that block");
}

struct SolutionBlock {
    double time = 0.0;
    std::vector<float> values;
};

double derive(const std::string& variable, const std::array<double, 5>& q, double gamma) {
    if (variable == "density") return q[0];
    if (variable == "x-momentum") return q[1];
    if (variable == "y-momentum") return q[2];
    if (variable == "z-momentum") return q[3];
    if (variable == "energy") return q[4];
    const double momentumSquared = q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    if (variable == "momentum-magnitude") return std::sqrt(momentumSquared);
    return (gamma - 1.0) * (q[4] - 0.5 * momentumSquared / q[0]);  // pressure
}

SolutionBlock readSolutionBlock(const Plot3DFile& file, const Plot3DOptions& options, const GridBlock& grid,
                                const std::filesystem::path& gridFile) {
    requireBlock(file, options.block);
    const auto block = std::size_t(options.block);
    const glm::ivec3 dims = file.layout.dims[block];
    requireMatchingDims(file, options.block, grid, gridFile);
    if (functionIndex(options.variable))
        throwInputError(file.path, "--var", options.variable + " names a variable of a function (.f) file, not of a "
                                                               "solution (q) file");
    const std::size_t nodes = grid.grid.voxelCount();
    const std::size_t precision = std::size_t(file.layout.precision);
    SolutionBlock result;
    result.time = file.real(file.layout.blockOffsets[block] + 3 * precision);
    const std::size_t arrays = file.layout.solutionArrayOffsets[block];
    static const std::array<const char*, 5> names = {"density", "x-momentum", "y-momentum", "z-momentum", "energy"};
    result.values.resize(nodes);
    for (std::size_t node = 0; node < nodes; ++node) {
        std::array<double, 5> q{};
        bool unknown = false;  // NaN in any component: the solver left the node without data
        for (std::size_t component = 0; component < 5; ++component) {
            q[component] = file.real(arrays + (component * nodes + node) * precision);
            if (std::isinf(q[component]))
                throwInputError(file.path, "", std::string("infinite ") + names[component] + " at node " +
                                                   nodeText(dims, node) + " of block " + std::to_string(block));
            unknown = unknown || std::isnan(q[component]);
        }
        if (grid.blanked[node] || unknown) {
            result.values[node] = missingDensity();
            continue;
        }
        if (options.variable == "pressure" && !(q[0] > 0.0))
            throwInputError(file.path, "", "density " + std::to_string(q[0]) + " at node " + nodeText(dims, node) +
                                               " of block " + std::to_string(block) +
                                               ": pressure needs a positive density");
        const double value = derive(options.variable, q, options.gamma);
        if (!std::isfinite(value) || std::abs(value) > std::numeric_limits<float>::max())
            throwInputError(file.path, "", options.variable + " is not finite at node " + nodeText(dims, node));
        result.values[node] = float(value);
    }
    return result;
}

SolutionBlock readFunctionBlock(const Plot3DFile& file, const Plot3DOptions& options, const GridBlock& grid,
                                const std::filesystem::path& gridFile) {
    requireBlock(file, options.block);
    const auto block = std::size_t(options.block);
    const glm::ivec3 dims = file.layout.dims[block];
    requireMatchingDims(file, options.block, grid, gridFile);
    const auto function = functionIndex(options.variable);
    if (!function)
        throwInputError(file.path, "--var", "a function file holds variables function-0, function-1, ...; '" +
                                                options.variable + "' is a solution (q) variable");
    const int functions = file.layout.functionCounts[block];
    if (*function >= functions)
        throwInputError(file.path, "--var", "block " + std::to_string(block) + " has " + std::to_string(functions) +
                                                " function(s); " + options.variable + " was asked for");
    const std::size_t nodes = grid.grid.voxelCount();
    const std::size_t start =
        file.layout.blockOffsets[block] + std::size_t(*function) * nodes * std::size_t(file.layout.precision);
    SolutionBlock result{std::numeric_limits<double>::quiet_NaN(), std::vector<float>(nodes)};  // no time stored
    for (std::size_t node = 0; node < nodes; ++node) {
        const double value = file.real(start + node * std::size_t(file.layout.precision));
        if (std::isinf(value) || std::abs(value) > std::numeric_limits<float>::max())
            throwInputError(file.path, "", "infinite " + options.variable + " at node " + nodeText(dims, node) +
                                               " of block " + std::to_string(block) + " (in float32)");
        result.values[node] = grid.blanked[node] || std::isnan(value) ? missingDensity() : float(value);
    }
    return result;
}

void checkOptions(const Plot3DOptions& options) {
    const auto names = plot3DVariableNames();
    if (std::find(names.begin(), names.end(), options.variable) == names.end() && !functionIndex(options.variable)) {
        std::string known;
        for (const std::string& name : names) known += (known.empty() ? "" : ", ") + name;
        throwInputError("", "--var",
                        "unknown Plot3D variable '" + options.variable + "' (known: " + known +
                            "; function-0, function-1, ... for function files)");
    }
    if (!(options.gamma > 1.0) || !std::isfinite(options.gamma))
        throwInputError("", "--gamma", "must be a finite number greater than 1");
}

}  // namespace

std::vector<std::string> plot3DVariableNames() {
    return {"density", "x-momentum", "y-momentum", "z-momentum", "energy", "momentum-magnitude", "pressure"};
}

bool hasPlot3DGridExtension(const std::filesystem::path& path) {
    const std::string extension = lowercaseExtension(path);
    return extension == ".xyz" || extension == ".x" || extension == ".g" || extension == ".grd";
}

SourceSeries openPlot3DSource(const Plot3DOptions& options) {
    checkOptions(options);
    const Plot3DFile gridFile = readPlot3DFile(options.gridFile, Plot3DKind::GridFile);
    auto grid = std::make_shared<const GridBlock>(readGridBlock(gridFile, options.block));
    // Checked after the grid: a file that is no Plot3D grid at all should be reported as such.
    if (options.solutionFiles.empty())
        throwInputError(options.gridFile, "--solution",
                        "a Plot3D grid needs at least one solution (q) file: one per time-step");

    SourceSeries source;
    source.name = options.gridFile.stem().string() + " (" + options.variable + ")";
    source.file = options.gridFile;
    source.format = "Plot3D";
    std::vector<double> times;
    for (const std::filesystem::path& path : options.solutionFiles) {
        // The whole file is read (and checked) now for its layout and time, and again for its values.
        const bool functionFile = hasFunctionExtension(path);
        const Plot3DFile solution =
            readPlot3DFile(path, functionFile ? Plot3DKind::FunctionFile : Plot3DKind::SolutionFile);
        requireBlock(solution, options.block);
        requireMatchingDims(solution, options.block, *grid, options.gridFile);
        times.push_back(functionFile ? std::numeric_limits<double>::quiet_NaN()
                                     : solution.real(solution.layout.blockOffsets[std::size_t(options.block)] +
                                                     3 * std::size_t(solution.layout.precision)));
        SourceStep step;
        step.grid = grid->grid;
        step.type = solution.layout.precision == 8 ? ValueType::Float64 : ValueType::Float32;
        step.file = path;
        source.steps.push_back(std::move(step));
    }
    const bool increasing = std::adjacent_find(times.begin(), times.end(), std::greater_equal<double>()) == times.end();
    for (std::size_t index = 0; index < source.steps.size(); ++index)
        source.steps[index].time = increasing && std::isfinite(times[index]) ? times[index] : double(index);

    source.readStep = [options, grid](std::size_t index) {
        const std::filesystem::path& path = options.solutionFiles[index];
        const bool functionFile = hasFunctionExtension(path);
        const Plot3DFile solution =
            readPlot3DFile(path, functionFile ? Plot3DKind::FunctionFile : Plot3DKind::SolutionFile);
        SolutionBlock block = functionFile ? readFunctionBlock(solution, options, *grid, options.gridFile)
                                           : readSolutionBlock(solution, options, *grid, options.gridFile);
        if (std::all_of(block.values.begin(), block.values.end(), [](float value) { return isMissing(value); }))
            throwInputError(path, "", "every node of block " + std::to_string(options.block) + " is blanked (IBLANK 0)");
        return std::move(block.values);
    };
    return source;
}

bool looksLikePlot3DGrid(const std::filesystem::path& file) {
    try {
        readPlot3DFile(file, Plot3DKind::GridFile);
        return true;
    } catch (const InputError&) {
        return false;
    }
}

Series readPlot3D(const Plot3DOptions& options) {
    const SourceSeries source = openPlot3DSource(options);
    Series series;
    series.name = source.name;
    series.manifestPath = source.file;
    series.sourceFormat = source.format;
    for (std::size_t index = 0; index < source.steps.size(); ++index) {
        const SourceStep& from = source.steps[index];
        TimeStep step;
        step.time = from.time;
        step.grid = from.grid;
        step.sourceType = ValueType::Float32;
        step.valuesFile = from.file;
        step.density = source.readStep(index);
        step.rawRange = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
        for (float value : step.density)
            if (!isMissing(value)) {
                step.rawRange[0] = std::min(step.rawRange[0], double(value));
                step.rawRange[1] = std::max(step.rawRange[1], double(value));
            }
        series.steps.push_back(std::move(step));
    }

    series.valueRange = series.steps.front().rawRange;
    for (const TimeStep& step : series.steps) {
        series.valueRange[0] = std::min(series.valueRange[0], step.rawRange[0]);
        series.valueRange[1] = std::max(series.valueRange[1], step.rawRange[1]);
    }
    if (series.valueRange[0] == series.valueRange[1]) series.valueRange[1] = series.valueRange[0] + 1.0;
    for (TimeStep& step : series.steps)
        for (float& value : step.density)
            if (!isMissing(value))
                value = float(std::clamp((double(value) - series.valueRange[0]) /
                                             (series.valueRange[1] - series.valueRange[0]), 0.0, 1.0));
    return series;
}

}  // namespace tstyles
