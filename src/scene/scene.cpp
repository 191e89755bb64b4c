// The names that scene files, the CLI and the viewer use for temporal compositors and final modes.
#include "tstyles/scene/scene.h"

#include <array>
#include <utility>

#include "name_table.h"
#include "tstyles/core/errors.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

// One table per enum, so that the name of a value and the value of a name cannot drift apart.
constexpr std::array finalModeNameTable{
    std::pair{FinalMode::Stf, "stf"},
    std::pair{FinalMode::Tstf, "tstf"},
    std::pair{FinalMode::Modulate, "modulate"},
};

}  // namespace

std::string toString(TemporalCompositor tc) { return compositorInfo(tc).name; }

std::optional<TemporalCompositor> temporalCompositorFromString(const std::string& name) {
    for (const auto& info : temporalCompositors())
        if (name == info.name) return info.compositor;
    return std::nullopt;
}

std::string toString(FinalMode mode) { return nameOf(finalModeNameTable, mode); }

std::optional<FinalMode> finalModeFromString(const std::string& name) {
    return valueOf(finalModeNameTable, name);
}

std::vector<std::string> temporalCompositorNames() {
    std::vector<std::string> names;
    for (const auto& info : temporalCompositors())
        if (info.compositor != TemporalCompositor::Custom) names.emplace_back(info.name);
    return names;
}

std::vector<std::string> finalModeNames() { return allNames(finalModeNameTable); }

}  // namespace tstyles

namespace tstyles {

glm::ivec2 CompositorOptions::differenceSteps(std::size_t stepCount, const std::filesystem::path& sceneFile) const {
    const int lastStep = int(stepCount) - 1;
    const int to = differenceTo.value_or(lastStep);
    for (const auto& [index, step] : {std::pair{0, differenceFrom}, std::pair{1, to}})
        if (step < 0 || step > lastStep)
            throwInputError(sceneFile, "compositor.steps[" + std::to_string(index) + "]",
                            "is " + std::to_string(step) + " (the series has " + std::to_string(stepCount) +
                                " time-steps, 0 to " + std::to_string(lastStep) + ")");
    return {differenceFrom, to};
}

std::optional<std::string> Exposure::orderProblem() const {
    if (!last || *last >= first) return std::nullopt;
    return "is " + std::to_string(*last) + ", before exposure.first (" + std::to_string(first) + ")";
}

glm::ivec2 Exposure::stepsOf(std::size_t stepCount, const std::filesystem::path& sceneFile) const {
    const int lastStep = int(stepCount) - 1;
    const std::string available = " (the series has " + std::to_string(stepCount) + " time-steps, 0 to " +
                                  std::to_string(lastStep) + ")";
    if (first < 0 || first > lastStep)
        throwInputError(sceneFile, "exposure.first", "is " + std::to_string(first) + available);
    const int end = last.value_or(lastStep);
    if (end > lastStep) throwInputError(sceneFile, "exposure.last", "is " + std::to_string(end) + available);
    // Without a last, the last time-step is at or after first (checked above).
    if (const auto problem = orderProblem()) throwInputError(sceneFile, "exposure.last", *problem);
    return {first, end};
}

}  // namespace tstyles
