// Lookups in the table of ray modes (ray_modes.h), the scene's ray-mode options, and which ray
// modes go with which compositors.
#include "tstyles/scene/ray_modes.h"

#include <algorithm>

#include "tstyles/scene/scene.h"

namespace tstyles {

const RayModeOption* RayModeOptionList::find(std::string_view key) const {
    const auto found = std::find_if(begin(), end(), [&](const RayModeOption& option) { return key == option.key; });
    return found == end() ? nullptr : found;
}

std::span<const RayModeInfo> rayModes() { return kRayModes; }

const RayModeInfo& rayModeInfo(RayMode mode) { return kRayModes.at(mode.line()); }

std::string toString(RayMode mode) { return rayModeInfo(mode).name; }

std::optional<RayMode> rayModeFromString(const std::string& name) {
    for (const RayMode mode : allRayModes())
        if (name == rayModeInfo(mode).name) return mode;
    return std::nullopt;
}

std::vector<RayMode> allRayModes() {
    std::vector<RayMode> modes;
    for (std::size_t line = 0; line < kRayModes.size(); ++line) modes.emplace_back(line);
    return modes;
}

std::vector<std::string> rayModeNames() {
    std::vector<std::string> names;
    for (const RayModeInfo& info : kRayModes) names.emplace_back(info.name);
    return names;
}

std::vector<const RayModeOption*> rayModeOptionsOfAll() {
    std::vector<const RayModeOption*> options;
    for (const RayModeInfo& info : kRayModes)
        for (const RayModeOption& option : info.options)
            if (std::none_of(options.begin(), options.end(),
                             [&](const RayModeOption* known) { return std::string_view(known->key) == option.key; }))
                options.push_back(&option);
    return options;
}

std::vector<std::string> rayModesTaking(std::string_view key) {
    std::vector<std::string> names;
    for (const RayModeInfo& info : kRayModes)
        if (info.options.find(key)) names.emplace_back(info.name);
    return names;
}

double RayModeOptions::number(const RayModeOption& option) const {
    const auto found = values.find(std::string_view(option.key));
    if (found == values.end()) return option.defaultNumber;
    const double* number = std::get_if<double>(&found->second);
    return number ? *number : option.defaultNumber;
}

std::vector<double> RayModeOptions::numbers(const RayModeOption& option) const {
    const auto found = values.find(std::string_view(option.key));
    if (found != values.end())
        if (const auto* list = std::get_if<std::vector<double>>(&found->second)) return *list;
    std::size_t count = 1;
    if (option.countOf)
        for (const RayModeOption* other : rayModeOptionsOfAll())
            if (std::string_view(other->key) == option.countOf) count = numbers(*other).size();
    return std::vector<double>(count, option.defaultNumber);
}

bool RayModeOptions::operator==(const RayModeOptions& other) const {
    for (const RayModeOption* option : rayModeOptionsOfAll()) {
        const bool same = option->kind == RayModeOptionKind::Number ? number(*option) == other.number(*option)
                                                                    : numbers(*option) == other.numbers(*option);
        if (!same) return false;
    }
    return true;
}

std::optional<RayModeProblem> rayModeProblem(const Scene& scene) {
    const RayModeInfo& mode = rayModeInfo(scene.rayMode);
    const CompositorReads reads = compositorReads(scene);
    if (mode.needsValue && reads == CompositorReads::Composited)
        return RayModeProblem{"ray.mode", std::string(mode.name) + " compares a value along the ray, and " +
                                              toString(scene.compositor) +
                                              " composites the time-steps' colours, which have none; use composite, "
                                              "average or additive with it, or a compositor that picks a time-step"};
    if (mode.readsChange && reads == CompositorReads::IndexTstf && !compositorInfo(scene.compositor).takesUnchanged)
        return RayModeProblem{"ray.mode", std::string(mode.name) + " compares how much each place changes over time, "
                                              "which the built-in compositors that pick a time-step measure (" +
                                              listedNames(compositorsTakingUnchanged()) + "), and " +
                                              toString(scene.compositor) + " does not"};
    // Compositors that pick a time-step show its density, in [0, 1].
    if (const RayModeOption* values = mode.options.find("values"); values && reads == CompositorReads::IndexTstf) {
        const std::vector<double> isoValues = scene.rayOptions.numbers(*values);
        for (std::size_t i = 0; i < isoValues.size(); ++i)
            if (isoValues[i] < 0.0)
                return RayModeProblem{"ray.values[" + std::to_string(i) + "]",
                                      "must be in [0, 1], got " + formatNumber(isoValues[i]) + ": " +
                                          toString(scene.compositor) +
                                          " shows densities, which the data's range maps to [0, 1]"};
    }
    return std::nullopt;
}

}  // namespace tstyles
