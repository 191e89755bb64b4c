// The ray mode in the compositor section: the table's modes in a list, and the chosen mode's
// options (ray_modes.h) as sliders, one per number.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "key_slider.h"
#include "side_panel.h"
#include "tstyles/scene/ray_mode_switch.h"
#include "tstyles/scene/ray_modes.h"

namespace tstyles::viewer {
namespace {

// The modes the compositor goes with (rayModeProblem): a mode that needs a value is not offered
// with a compositor that composites the time-steps, nor one that reads the change with a
// compositor that picks no time-step.
std::vector<RayMode> offeredRayModes(const Scene& scene) {
    std::vector<RayMode> offered;
    for (const RayMode mode : allRayModes()) {
        Scene trial = scene;
        trial.rayMode = mode;
        const std::optional<RayModeProblem> problem = rayModeProblem(trial);
        if (!problem || problem->key != "ray.mode") offered.push_back(mode);
    }
    return offered;
}

// A mode chosen in the list comes with its automatic STF and step where the scene has the current
// mode's automatic ones (switchRayMode).
void drawRayModeChoice(Scene& scene, const Series& shown) {
    const std::vector<RayMode> offered = offeredRayModes(scene);
    if (ImGui::BeginCombo("ray", toString(scene.rayMode).c_str())) {
        for (const RayMode mode : offered) {
            const RayModeInfo& info = rayModeInfo(mode);
            if (ImGui::Selectable(info.name, mode == scene.rayMode)) switchRayMode(scene, shown, mode);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", info.summary);
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("How the samples along a ray make the pixel: %s (docs/ray-modes.md). A mode chosen here "
                          "brings its own automatic STF and ray step where you have not changed the current ones.",
                          rayModeInfo(scene.rayMode).summary);
}

// A list option: a slider per entry, and + / - for the lists that set their own length (the
// others follow the list whose length they take, `countOf`).
void drawNumberList(const RayModeOption& option, RayModeOptions& options) {
    std::vector<double> numbers = options.numbers(option);
    bool changed = false;
    for (std::size_t index = 0; index < numbers.size(); ++index) {
        const std::string label = std::string(option.key) + "[" + std::to_string(index) + "]";
        changed |= ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &numbers[index], &option.range.low,
                                       &option.range.high, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("ray.%s: %s", option.key, option.help);
    }
    if (!option.countOf) {
        const std::string add = std::string("+##") + option.key;
        const std::string remove = std::string("-##") + option.key;
        ImGui::BeginDisabled(numbers.size() >= option.maxCount);
        if (ImGui::Button(add.c_str())) {
            numbers.push_back(numbers.back());
            changed = true;
        }
        ImGui::EndDisabled();
        ImGui::SameLine();
        ImGui::BeginDisabled(numbers.size() <= 1);
        if (ImGui::Button(remove.c_str())) {
            numbers.pop_back();
            changed = true;
        }
        ImGui::EndDisabled();
        ImGui::SameLine();
        ImGui::TextDisabled("%zu of at most %zu %s", numbers.size(), option.maxCount, option.key);
    }
    if (!changed) return;
    // The lists that take this one's length follow it: an added entry takes its default.
    for (const RayModeOption* other : rayModeOptionsOfAll())
        if (other->countOf && std::string_view(other->countOf) == option.key) {
            std::vector<double> following = options.numbers(*other);
            following.resize(numbers.size(), other->defaultNumber);
            options.values[other->key] = following;
        }
    options.values[option.key] = std::move(numbers);
}

void drawRayModeOptions(Scene& scene) {
    for (const RayModeOption& option : rayModeInfo(scene.rayMode).options) {
        switch (option.kind) {
            case RayModeOptionKind::Number: {
                double value = scene.rayOptions.number(option);
                if (drawKeySlider({option.key, std::string("ray.") + option.key, "%.3f"}, value))
                    scene.rayOptions.values[option.key] = value;
                break;
            }
            case RayModeOptionKind::NumberList:
                drawNumberList(option, scene.rayOptions);
                break;
        }
    }
}

}  // namespace

void drawRayModeSection(Scene& scene, const Series& shown) {
    // A compositor chosen after the mode may not go with it: the ray composites again.
    if (const auto problem = rayModeProblem(scene); problem && problem->key == "ray.mode") scene.rayMode = kCompositeRay;
    drawRayModeChoice(scene, shown);
    drawRayModeOptions(scene);
    // Iso-values below 0 mean nothing where the compositor shows densities.
    if (const RayModeOption* values = rayModeInfo(scene.rayMode).options.find("values");
        values && rayModeProblem(scene)) {
        std::vector<double> numbers = scene.rayOptions.numbers(*values);
        for (double& number : numbers) number = std::max(number, 0.0);
        scene.rayOptions.values[values->key] = std::move(numbers);
    }
}

}  // namespace tstyles::viewer
