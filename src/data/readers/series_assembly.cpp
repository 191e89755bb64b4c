// The format-independent half of reading: which steps, how much memory, what resolution, what range.
#include "series_assembly.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <variant>

#include "../raw_values.h"
#include "resampling.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

std::string planDimsText(const glm::ivec3& dims) {
    return std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " + std::to_string(dims.z);
}

// Host memory (one float per voxel) plus the GPU's copy at the chosen precision.
double bytesPerVoxel(const ReadOptions& options) {
    return double(sizeof(float) + bytesPerDensity(options.precision));
}

double voxelCount(const glm::ivec3& dims) {
    return double(dims.x) * double(dims.y) * double(dims.z);
}

struct Plan {
    std::vector<std::size_t> steps;
    std::vector<glm::ivec3> dims;  // per kept step
};

double planBytes(const Plan& plan, const ReadOptions& options) {
    double voxels = 0.0;
    for (const glm::ivec3& dims : plan.dims) voxels += voxelCount(dims);
    return voxels * bytesPerVoxel(options);
}

Plan initialPlan(const SourceSeries& source, const ReadOptions& options) {
    Plan plan;
    plan.steps = selectedSteps(options.steps, source.steps.size());
    if (plan.steps.empty()) {
        throwInputError(source.file, "--steps",
                        "selects no time-step: the file holds " + std::to_string(source.steps.size()) +
                            " (indices 0 to " + std::to_string(source.steps.size() - 1) + ")");
    }
    for (std::size_t index : plan.steps) {
        if (options.resampleTo && std::holds_alternative<StructuredGrid>(source.steps[index].grid))
            throwInputError(source.file, "--resample",
                            "applies to rectilinear grids; a structured (Plot3D) grid is read at its own nodes");
        plan.dims.push_back(options.resampleTo.value_or(gridDims(source.steps[index].grid)));
    }
    return plan;
}

bool anyStructured(const SourceSeries& source) {
    return std::any_of(source.steps.begin(), source.steps.end(),
                       [](const SourceStep& step) { return std::holds_alternative<StructuredGrid>(step.grid); });
}

[[noreturn]] void refuse(const SourceSeries& source, const Plan& plan, const ReadOptions& options,
                         const std::string& remedy) {
    const glm::ivec3 largest = *std::max_element(plan.dims.begin(), plan.dims.end(), [](auto a, auto b) {
        return voxelCount(a) < voxelCount(b);
    });
    throwInputError(source.file, "--max-memory",
                    "the series needs " + byteCountText(planBytes(plan, options)) + " (" +
                        std::to_string(plan.steps.size()) + " time-steps of up to " + planDimsText(largest) +
                        " voxels, 4 bytes each in memory and " + std::to_string(bytesPerDensity(options.precision)) +
                        " on the GPU), more than the " + byteCountText(double(memoryCap(options.maxMemoryBytes))) +
                        (options.maxMemoryBytes ? " allowed: " : " allowed by default (half of this machine's memory): ") +
                        remedy);
}

// Fewer time-steps, spread evenly over the selection, first and last kept.
void fitBySteps(const SourceSeries& source, Plan& plan, const ReadOptions& options) {
    const double allowed = double(memoryCap(options.maxMemoryBytes));
    double largestStep = 0.0;
    for (const glm::ivec3& dims : plan.dims) largestStep = std::max(largestStep, voxelCount(dims) * bytesPerVoxel(options));
    const std::size_t keep = std::min(plan.steps.size(), std::size_t(allowed / largestStep));
    if (keep == 0) refuse(source, plan, options, "not even one time-step fits; allow more, or add --fit resolution");
    Plan fewer;
    for (std::size_t j = 0; j < keep; ++j) {
        const std::size_t pick =
            keep == 1 ? 0 : std::size_t(std::lround(double(j) * double(plan.steps.size() - 1) / double(keep - 1)));
        fewer.steps.push_back(plan.steps[pick]);
        fewer.dims.push_back(plan.dims[pick]);
    }
    plan = fewer;
}

// Every time-step shrunk by one factor until the series fits.
void fitByResolution(const SourceSeries& source, Plan& plan, const ReadOptions& options) {
    if (anyStructured(source))
        refuse(source, plan, options, "a structured (Plot3D) grid cannot be read at a lower resolution; allow more, "
                                      "or add --fit steps");
    const double allowed = double(memoryCap(options.maxMemoryBytes));
    double scale = std::cbrt(planBytes(plan, options) / allowed);
    const std::vector<glm::ivec3> original = plan.dims;
    for (int attempt = 0; attempt < 64 && planBytes(plan, options) > allowed; ++attempt) {
        for (std::size_t index = 0; index < plan.dims.size(); ++index)
            plan.dims[index] = glm::max(glm::ivec3(2), glm::ivec3(glm::dvec3(original[index]) / scale));
        scale *= 1.02;
    }
    if (planBytes(plan, options) > allowed)
        refuse(source, plan, options, "even at 2 x 2 x 2 voxels it does not fit; allow more, or add --fit steps");
}

std::array<double, 2> rangeOf(const std::vector<float>& values) {
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -lowest;
    for (float value : values) {
        if (isMissing(value)) continue;
        lowest = std::min(lowest, double(value));
        highest = std::max(highest, double(value));
    }
    const double none = std::numeric_limits<double>::quiet_NaN();
    return lowest <= highest ? std::array<double, 2>{lowest, highest} : std::array<double, 2>{none, none};
}

std::array<double, 2> rangeFromData(const SourceSeries& source, const Series& series) {
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -lowest;
    for (const TimeStep& step : series.steps) {
        if (std::isnan(step.rawRange[0])) continue;
        lowest = std::min(lowest, step.rawRange[0]);
        highest = std::max(highest, step.rawRange[1]);
    }
    if (!(lowest <= highest))
        throwInputError(source.file, "", "every value of the chosen time-steps is missing: there is nothing to show");
    if (lowest == highest) {
        std::ostringstream value;
        value << lowest;
        throwInputError(source.file, "--range",
                        "every value of the chosen time-steps is " + value.str() +
                            ", so no range can be derived: give --range LOW:HIGH");
    }
    return {lowest, highest};
}

}  // namespace

void requireStepCount(const std::filesystem::path& file, const std::string& field, std::uint64_t count) {
    if (count > kMaxTimeSteps)
        throwInputError(file, field,
                        "declares " + std::to_string(count) + " time-steps, more than the " +
                            std::to_string(kMaxTimeSteps) + " a series may have (damaged file?)");
    requireMemory(file, field, double(count) * double(sizeof(SourceStep) + sizeof(TimeStep)), defaultMemoryCap(),
                  "the descriptions of " + std::to_string(count) + " time-steps");
}

Series assembleRawSeries(const SourceSeries& source, const ReadOptions& options) {
    Plan plan = initialPlan(source, options);
    if (planBytes(plan, options) > double(memoryCap(options.maxMemoryBytes))) {
        if (options.fit == MemoryFit::Refuse)
            refuse(source, plan, options, "allow more, or add --fit resolution or --fit steps");
        if (options.fit == MemoryFit::Steps) fitBySteps(source, plan, options);
        else fitByResolution(source, plan, options);
    }

    Series series;
    series.name = source.name;
    series.manifestPath = source.file;
    series.axes = source.axes;
    series.time = source.time;
    series.valueUnit = source.valueUnit;
    for (std::size_t kept = 0; kept < plan.steps.size(); ++kept) {
        const SourceStep& from = source.steps[plan.steps[kept]];
        TimeStep step;
        step.time = from.time;
        step.placement = from.placement;
        step.sourceType = from.type;
        step.valuesFile = from.file;
        reportStage(options.monitor, from.file, "the " + source.format + " reader",
                    "reading time-step " + std::to_string(plan.steps[kept]));
        std::vector<float> values = source.readStep(plan.steps[kept]);
        reportStepRead(options.monitor, values.size() * sizeof(float));
        if (plan.dims[kept] == gridDims(from.grid)) {
            step.grid = from.grid;
        } else {
            const auto& grid = std::get<RectilinearGrid>(from.grid);  // structured grids are never resampled
            step.grid = resampledGrid(grid, plan.dims[kept]);
            values = resampleValues(values, grid, plan.dims[kept]);
        }
        step.rawRange = rangeOf(values);
        step.density = std::move(values);
        series.steps.push_back(std::move(step));
    }
    series.valueRange = options.valueRange ? *options.valueRange : rangeFromData(source, series);
    return series;
}

Series toDensity(Series raw) {
    for (TimeStep& step : raw.steps) normalizeToDensity(step.density, raw.valueRange);
    return raw;
}

}  // namespace tstyles
