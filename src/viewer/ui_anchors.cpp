// The anchor registry: last-published rectangles and mappings by name.
#include "ui_anchors.h"

namespace tstyles::viewer {

void UiAnchors::publish(const std::string& name, const ScreenRect& rect) {
    publish(name, rect, [rect](glm::dvec2 uv) { return rect.at(glm::vec2(uv)); });
}

void UiAnchors::publish(const std::string& name, const ScreenRect& rect, Mapping mapping) {
    anchors_[name] = Anchor{rect, std::move(mapping), frame_};
}

std::optional<glm::vec2> UiAnchors::resolve(const std::string& name,
                                            const std::optional<glm::dvec2>& parameters) const {
    const auto found = anchors_.find(name);
    if (found == anchors_.end() || !isCurrent(found->second)) return std::nullopt;
    if (!parameters) return found->second.rect.center();
    return found->second.mapping(*parameters);
}

std::string UiAnchors::currentNames() const {
    std::string names;
    for (const auto& [name, anchor] : anchors_) {
        if (!isCurrent(anchor)) continue;
        if (!names.empty()) names += ", ";
        names += name;
    }
    return names;
}

}  // namespace tstyles::viewer
