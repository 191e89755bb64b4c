// Lookups in the table of temporal compositors (temporal_compositors.h).
#include "tstyles/scene/temporal_compositors.h"

#include <algorithm>

#include "tstyles/scene/scene.h"

namespace tstyles {

std::optional<std::size_t> CompositorOption::choiceNamed(std::string_view name) const {
    for (std::size_t i = 0; i < choiceCount(); ++i)
        if (name == choices[i]) return i;
    return std::nullopt;
}

std::vector<std::string> CompositorOption::choiceNames() const {
    return {choices.begin(), choices.begin() + std::ptrdiff_t(choiceCount())};
}

const CompositorOption* CompositorOptionList::find(std::string_view key) const {
    const auto found = std::find_if(begin(), end(), [&](const CompositorOption& option) { return key == option.key; });
    return found == end() ? nullptr : found;
}

std::span<const TemporalCompositorInfo> temporalCompositors() { return kTemporalCompositors; }

const TemporalCompositorInfo& compositorInfo(TemporalCompositor compositor) {
    return kTemporalCompositors.at(compositor.line());
}

std::string toString(TemporalCompositor compositor) { return compositorInfo(compositor).name; }

std::optional<TemporalCompositor> temporalCompositorFromString(const std::string& name) {
    for (const TemporalCompositor compositor : builtInCompositors())
        if (name == compositorInfo(compositor).name) return compositor;
    return std::nullopt;
}

std::vector<TemporalCompositor> builtInCompositors() {
    std::vector<TemporalCompositor> compositors;
    for (std::size_t line = 0; line < kTemporalCompositors.size(); ++line)
        if (TemporalCompositor(line) != kCustomCompositor) compositors.emplace_back(line);
    return compositors;
}

std::vector<std::string> temporalCompositorNames() {
    std::vector<std::string> names;
    for (const TemporalCompositor compositor : builtInCompositors())
        names.emplace_back(compositorInfo(compositor).name);
    return names;
}

CompositorReads compositorReads(const Scene& scene) {
    if (scene.compositor == kCustomCompositor && scene.compositorOptions.custom)
        return scene.compositorOptions.custom->reads;
    return compositorInfo(scene.compositor).reads;
}

std::vector<const CompositorOption*> compositorOptionsOfAll() {
    std::vector<const CompositorOption*> options;
    for (const TemporalCompositorInfo& info : kTemporalCompositors)
        for (const CompositorOption& option : info.options)
            if (std::none_of(options.begin(), options.end(),
                             [&](const CompositorOption* known) { return std::string_view(known->key) == option.key; }))
                options.push_back(&option);
    return options;
}

std::vector<std::string> compositorsTaking(std::string_view key) {
    std::vector<std::string> names;
    for (const TemporalCompositorInfo& info : kTemporalCompositors)
        if (info.options.find(key)) names.emplace_back(info.name);
    return names;
}

std::vector<std::string> compositorsTakingUnchanged() {
    std::vector<std::string> names;
    for (const TemporalCompositorInfo& info : kTemporalCompositors)
        if (info.takesUnchanged) names.emplace_back(info.name);
    return names;
}

std::string listedNames(const std::vector<std::string>& names, std::string_view quote) {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) text += i + 1 == names.size() ? " and " : ", ";
        text += std::string(quote) + names[i] + std::string(quote);
    }
    return text;
}

}  // namespace tstyles
