// Sliders for numeric scene keys, with ranges and tooltips from the table of keys.
#include "key_slider.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <imgui.h>

#include "tstyles/scene/scene_keys.h"

namespace tstyles::viewer {
namespace {

// The key's text for a tooltip: without markdown's backticks.
std::string plainText(std::string text) {
    std::erase(text, '`');
    return text;
}

}  // namespace

bool drawKeySlider(const KeySlider& slider, double& value) {
    const SceneKey& key = sceneKey(slider.keyPath);
    if (!key.numeric) throw std::logic_error("scene key \"" + std::string(slider.keyPath) + "\" holds no number");
    const Interval& range = key.numeric->range;
    const Interval shown = slider.shown.value_or(range);
    if (!range.contains(shown.low) || !range.contains(shown.high) || std::isinf(shown.low) || std::isinf(shown.high))
        throw std::logic_error("the slider of \"" + std::string(slider.keyPath) + "\" shows values outside " +
                               range.describe());
    const ImGuiSliderFlags flags =
        ImGuiSliderFlags_AlwaysClamp | (slider.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
    const bool changed =
        ImGui::SliderScalar(slider.label, ImGuiDataType_Double, &value, &shown.low, &shown.high, slider.format, flags);
    if (ImGui::IsItemHovered()) {
        std::string tooltip = std::string(key.path) + ": " + plainText(allowedText(key));
        if (slider.tooltipDetail) tooltip += "\n" + std::string(slider.tooltipDetail);
        ImGui::SetTooltip("%s", tooltip.c_str());
    }
    return changed;
}

}  // namespace tstyles::viewer
