// The names of the final modes, and what the scene's compositor options, exposure and other parts hold.
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

std::string toString(FinalMode mode) { return nameOf(finalModeNameTable, mode); }

std::optional<FinalMode> finalModeFromString(const std::string& name) {
    return valueOf(finalModeNameTable, name);
}

std::vector<std::string> finalModeNames() { return allNames(finalModeNameTable); }

bool CompositorOptions::operator==(const CompositorOptions& other) const {
    if (custom != other.custom || unchanged != other.unchanged) return false;
    for (const CompositorOption* option : compositorOptionsOfAll()) {
        switch (option->kind) {
            case CompositorOptionKind::Number:
                if (number(*option) != other.number(*option)) return false;
                break;
            case CompositorOptionKind::TimeStepPair:
                if (timeSteps(*option) != other.timeSteps(*option)) return false;
                break;
            case CompositorOptionKind::Choice:
                if (choice(*option) != other.choice(*option)) return false;
                break;
        }
    }
    return true;
}

double CompositorOptions::number(const CompositorOption& option) const {
    const double* given = givenValue<double>(option);
    return given ? *given : option.defaultNumber;
}

std::size_t CompositorOptions::choice(const CompositorOption& option) const {
    const std::string* given = givenValue<std::string>(option);
    return given ? option.choiceNamed(*given).value_or(0) : 0;
}

TimeStepPair CompositorOptions::timeSteps(const CompositorOption& option) const {
    const TimeStepPair* given = givenValue<TimeStepPair>(option);
    return given ? *given : TimeStepPair{};
}

glm::ivec2 CompositorOptions::timeStepsOn(const CompositorOption& option, std::size_t stepCount,
                                          const std::filesystem::path& sceneFile) const {
    const TimeStepPair steps = timeSteps(option);
    const int lastStep = int(stepCount) - 1;
    const int to = steps.to.value_or(lastStep);
    for (const auto& [index, step] : {std::pair{0, steps.from}, std::pair{1, to}})
        if (step < 0 || step > lastStep)
            throwInputError(sceneFile, "compositor." + std::string(option.key) + "[" + std::to_string(index) + "]",
                            "is " + std::to_string(step) + " (the series has " + std::to_string(stepCount) +
                                " time-steps, 0 to " + std::to_string(lastStep) + ")");
    return {steps.from, to};
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

void checkTimeStepsFit(const Scene& scene, std::size_t stepCount, const std::filesystem::path& sceneFile) {
    scene.exposure.stepsOf(stepCount, sceneFile);
    for (const CompositorOption& option : compositorInfo(scene.compositor).options)
        if (option.kind == CompositorOptionKind::TimeStepPair)
            scene.compositorOptions.timeStepsOn(option, stepCount, sceneFile);
}

}  // namespace tstyles
