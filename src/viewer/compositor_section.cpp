// The compositor and camera sections: how samples are combined (the ray mode's part is
// ray_mode_section.cpp), and from where the data is seen.
#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <imgui.h>

#include "camera_controller.h"
#include "key_slider.h"
#include "side_panel.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles::viewer {
namespace {

// A combo over names; returns the chosen index when it changed.
std::optional<std::size_t> nameCombo(const char* label, const std::vector<std::string>& names, const std::string& now) {
    std::optional<std::size_t> chosen;
    if (ImGui::BeginCombo(label, now.c_str())) {
        for (std::size_t i = 0; i < names.size(); ++i)
            if (ImGui::Selectable(names[i].c_str(), names[i] == now) && names[i] != now) chosen = i;
        ImGui::EndCombo();
    }
    return chosen;
}

void drawRaycastSettings(Scene& scene, double defaultStep) {
    bool automatic = !scene.raycast.step.has_value();
    if (ImGui::Checkbox("automatic step", &automatic))
        scene.raycast.step = automatic ? std::nullopt : std::optional<double>(defaultStep);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Half the finest voxel spacing: %.4g world units", defaultStep);
    if (scene.raycast.step) {
        double step = *scene.raycast.step;
        const double low = defaultStep * 0.1;
        const double high = defaultStep * 20.0;
        if (ImGui::SliderScalar("step", ImGuiDataType_Double, &step, &low, &high, "%.4g",
                                ImGuiSliderFlags_Logarithmic))
            scene.raycast.step = std::max(step, 1e-9);
    }
    // Below 0.05 a ray stops before it shows anything.
    drawKeySlider({"termination", "raycast.termination", "%.3f", false, Interval{0.05, 1.0}},
                  scene.raycast.termination);
}

// The gradient TSTF's range, in density units: signed characteristics (a trend, a difference)
// take a range around 0, the others one from 0.
void drawGradientRange(GradientTstf& tstf, CompositorReads reads) {
    if (reads != CompositorReads::GradientTstf) return;
    double range[2] = {tstf.rangeLow, tstf.rangeHigh};
    const double lowest = -1.0;
    const double highest = 1.0;
    if (ImGui::DragScalarN("range", ImGuiDataType_Double, range, 2, 0.002f, &lowest, &highest, "%.3f")) {
        // The scene format wants low < high.
        range[0] = std::clamp(range[0], lowest, highest - 0.001);
        range[1] = std::clamp(range[1], range[0] + 0.001, highest);
        tstf.rangeLow = range[0];
        tstf.rangeHigh = range[1];
        tstf.automaticRange = false;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Gradient TSTF: the compositor's value (in density units; a trend per unit of time) in "
                          "this range maps to [0, 1].");
}

void drawCompositorChoice(Scene& scene, const Series& series) {
    const std::vector<std::string> names = compositorChoices(scene);
    const std::string now =
        scene.compositor == kCustomCompositor ? kCustomCompositorChoice : toString(scene.compositor);
    if (auto chosen = nameCombo("compositor", names, now)) {
        scene.compositor = names[*chosen] == kCustomCompositorChoice ? kCustomCompositor
                                                                     : *temporalCompositorFromString(names[*chosen]);
        // "auto" fits the compositor (a trend's range is signed and per unit of time).
        if (scene.gradientTstf.automaticRange && series.size() > 0)
            std::tie(scene.gradientTstf.rangeLow, scene.gradientTstf.rangeHigh) = automaticGradientRange(scene, series);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", compositorInfo(scene.compositor).summary);
}

// Unchanged places (CompositorOptions::unchanged): on or off, the threshold (dragging it leaves
// "auto"), and the share of the STF's opacity they keep.
void drawUnchangedPlaces(Scene& scene, const Series& series) {
    std::optional<UnchangedTime>& unchanged = scene.compositorOptions.unchanged;
    bool on = unchanged.has_value();
    if (ImGui::Checkbox("time only where it changes", &on)) {
        unchanged.reset();
        if (on) {
            unchanged = UnchangedTime{};
            if (series.size() > 0) takeFit(*unchanged, automaticUnchangedFit(scene, series));
        }
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("No time colour where a place's values change by no more than the threshold, nor where two "
                          "time-steps tie (docs/compositors.md, \"Unchanged places\").");
    if (!unchanged) return;
    const char* belowLabel = unchanged->automatic ? "unchanged below (auto)" : "unchanged below";
    if (drawKeySlider({belowLabel, "compositor.unchanged.below", "%.4f", true, std::nullopt,
                       "\"auto\": a tenth of the typical largest change, or above the noise."},
                      unchanged->below))
        unchanged->automatic = false;
    if (drawKeySlider({"tie", "compositor.unchanged.tie", "%.4f", true, std::nullopt,
                       "\"auto\": what the data's noise puts between two equal values."},
                      unchanged->tie))
        unchanged->automatic = false;
    drawKeySlider({"unchanged opacity", "compositor.unchanged.opacity", "%.2f"}, unchanged->opacity);
    if (drawKeySlider({"changed gain", "compositor.unchanged.gain", "%.2f", false, std::nullopt,
                       "\"auto\": the ratio of the ray lengths through all visible places and through the "
                       "changing ones."},
                      unchanged->gain))
        unchanged->automatic = false;
    const double flattest = 0.0;
    if (ImGui::DragScalar("boundary", ImGuiDataType_Double, &unchanged->boundary, 0.01f, &flattest, nullptr, "%.3f"))
        unchanged->automatic = false;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Unchanged places keep their whole share of opacity where the value gradient is this steep "
                          "(density per length), less where it is flatter: regions of one value fade, boundaries "
                          "stay; 0: everywhere. \"auto\": the 99th percentile of the visible places' gradient.");
}

// One option of the chosen compositor, by its kind: a slider over a number's range (its scene key's
// line), two time-step sliders, or a list of choices.
void drawCompositorOption(const CompositorOption& option, CompositorOptions& options, const Series& series) {
    const std::string keyPath = std::string("compositor.") + option.key;
    switch (option.kind) {
        case CompositorOptionKind::Number: {
            double value = options.number(option);
            if (drawKeySlider({option.key, keyPath, "%.3f"}, value)) options.values[option.key] = value;
            return;  // drawKeySlider's tooltip is the key's line, which holds the option's help
        }
        case CompositorOptionKind::TimeStepPair: {
            if (series.size() == 0) return;
            const int last = int(series.size()) - 1;
            const TimeStepPair steps = options.timeSteps(option);
            int chosen[2] = {std::clamp(steps.from, 0, last), std::clamp(steps.to.value_or(last), 0, last)};
            const std::string label = std::string(option.key) + " (from, to)";
            if (ImGui::SliderInt2(label.c_str(), chosen, 0, last))
                options.values[option.key] =
                    TimeStepPair{std::clamp(chosen[0], 0, last), std::clamp(chosen[1], 0, last)};
            break;
        }
        case CompositorOptionKind::Choice: {
            const std::vector<std::string> names = option.choiceNames();
            if (const auto chosen = nameCombo(option.key, names, names[options.choice(option)]))
                options.values[option.key] = names[*chosen];
            break;
        }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", option.help);
}

// The options of the chosen compositor (its table line's), its unchanged places, or what the
// scene's own code is read by.
void drawCompositorOptions(Scene& scene, const Series& series) {
    const TemporalCompositorInfo& info = compositorInfo(scene.compositor);
    CompositorOptions& options = scene.compositorOptions;
    for (const CompositorOption& option : info.options) drawCompositorOption(option, options, series);
    if (info.takesUnchanged) drawUnchangedPlaces(scene, series);
    if (scene.compositor == kCustomCompositor && options.custom) {
        const bool index = options.custom->reads == CompositorReads::IndexTstf;
        ImGui::TextDisabled("the scene's own GLSL, read by the %s TSTF", index ? "index" : "gradient");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("From %s. Edit it there (docs/compositors.md) and open the scene again.",
                              options.custom->origin.string().c_str());
    }
}

}  // namespace

std::vector<std::string> compositorChoices(const Scene& scene) {
    std::vector<std::string> names = temporalCompositorNames();
    if (scene.compositorOptions.custom) names.emplace_back(kCustomCompositorChoice);
    return names;
}

void drawCompositorSection(SidePanelState& state) {
    Scene& scene = state.scene;
    drawCompositorChoice(scene, state.series);
    drawCompositorOptions(scene, state.series);
    drawRayModeSection(scene, state.series);
    if (auto chosen = nameCombo("final mode", finalModeNames(), toString(scene.finalMode)))
        scene.finalMode = *finalModeFromString(finalModeNames()[*chosen]);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("stf: STF alone; tstf: TSTF alone; modulate: STF times TSTF");
    drawRaycastSettings(scene, state.defaultStep);
    drawGradientRange(scene.gradientTstf, compositorReads(scene));
    float background[4] = {float(scene.background.r), float(scene.background.g), float(scene.background.b),
                           float(scene.background.a)};
    if (ImGui::ColorEdit4("background", background, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_AlphaPreviewHalf))
        scene.background = glm::clamp(glm::dvec4(background[0], background[1], background[2], background[3]),
                                      glm::dvec4(0.0), glm::dvec4(1.0));
}

void drawCameraSection(SidePanelState& state, ViewerCommands& commands) {
    Camera& camera = state.scene.camera;
    if (auto chosen = nameCombo("projection", projectionNames(), toString(camera.projection)))
        camera.projection = *projectionFromString(projectionNames()[*chosen]);
    // Wider than 120 degrees a perspective bends the data out of shape; narrower than 5 it shows a speck.
    drawKeySlider({"field of view", "camera.fov_deg", "%.1f deg", false, Interval{5.0, 120.0}}, camera.fovDeg);
    if (auto* orbit = std::get_if<OrbitCamera>(&camera.pose)) {
        drawKeySlider({"azimuth", "camera.orbit.azimuth_deg", "%.1f deg", false, Interval{-180.0, 180.0}},
                      orbit->azimuthDeg);
        // At a pole the orbit's up direction is undefined: the slider stops a degree short.
        drawKeySlider({"elevation", "camera.orbit.elevation_deg", "%.1f deg", false, Interval{-89.0, 89.0}},
                      orbit->elevationDeg);
        ImGui::TextDisabled("distance %s, target %s", orbit->distance ? "set" : "framing the data",
                            orbit->target ? "set" : "data centre");
    } else {
        ImGui::TextDisabled("look-at camera (dragging turns it into an orbit camera)");
    }
    if (ImGui::Button("Reset (R)")) commands.push_back(ViewerCommand::ResetCamera);
    ImGui::SameLine();
    if (ImGui::Button("Fit to data (F)")) commands.push_back(ViewerCommand::FitCamera);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("Drag: orbit. Shift+drag or middle drag: pan. Wheel or right drag: zoom. Ctrl+click: "
                        "temporal profile.");
    ImGui::PopTextWrapPos();
}

}  // namespace tstyles::viewer
