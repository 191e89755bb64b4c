// The compositor and camera sections: how samples are combined, and from where the data is seen.
#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <imgui.h>

#include "camera_controller.h"
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
    const double lowest = 0.05;
    const double highest = 1.0;
    ImGui::SliderScalar("termination", ImGuiDataType_Double, &scene.raycast.termination, &lowest, &highest, "%.3f");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Rays stop once their accumulated opacity reaches this.");
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
        scene.compositor == TemporalCompositor::Custom ? kCustomCompositorChoice : toString(scene.compositor);
    if (auto chosen = nameCombo("compositor", names, now)) {
        scene.compositor = names[*chosen] == kCustomCompositorChoice ? TemporalCompositor::Custom
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
    const double low = 0.0;
    const double high = 1.0;
    if (ImGui::SliderScalar(unchanged->automatic ? "unchanged below (auto)" : "unchanged below", ImGuiDataType_Double,
                            &unchanged->below, &low, &high, "%.4f", ImGuiSliderFlags_Logarithmic))
        unchanged->automatic = false;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("A change in density units (0 to 1); \"auto\" is fitted to the data: a tenth of the typical "
                          "largest change, or above the noise.");
    if (ImGui::SliderScalar("tie", ImGuiDataType_Double, &unchanged->tie, &low, &high, "%.4f",
                            ImGuiSliderFlags_Logarithmic))
        unchanged->automatic = false;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Two time-steps whose densities differ by no more than this tie (density units); \"auto\": "
                          "what the data's noise puts between two equal values.");
    ImGui::SliderScalar("unchanged opacity", ImGuiDataType_Double, &unchanged->opacity, &low, &high, "%.2f");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Unchanged places show the STF alone with this share of its opacity: 1 as the STF has it, 0 "
                          "transparent.");
    const double lowestGain = 1.0;
    const double highestGain = 8.0;
    if (ImGui::SliderScalar("changed gain", ImGuiDataType_Double, &unchanged->gain, &lowestGain, &highestGain, "%.2f"))
        unchanged->automatic = false;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Places that change show as if this many times as thick; \"auto\": the ratio of the ray "
                          "lengths through all visible places and through the changing ones.");
    const double flattest = 0.0;
    if (ImGui::DragScalar("boundary", ImGuiDataType_Double, &unchanged->boundary, 0.01f, &flattest, nullptr, "%.3f"))
        unchanged->automatic = false;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Unchanged places keep their whole share of opacity where the value gradient is this steep "
                          "(density per length), less where it is flatter: regions of one value fade, boundaries "
                          "stay; 0: everywhere. \"auto\": the 99th percentile of the visible places' gradient.");
}

// The options of the chosen compositor: a threshold, the two time-steps of a difference, or what
// the scene's own code is read by.
void drawCompositorOptions(Scene& scene, const Series& series) {
    const TemporalCompositorInfo& info = compositorInfo(scene.compositor);
    CompositorOptions& options = scene.compositorOptions;
    if (info.takesThreshold) {
        const double low = 0.0;
        const double high = 1.0;
        ImGui::SliderScalar("threshold", ImGuiDataType_Double, &options.threshold, &low, &high, "%.3f");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("The density (0 to 1) a time-step must reach at the sample.");
    }
    if (info.takesSteps && series.size() > 0) {
        const int last = int(series.size()) - 1;
        int chosen[2] = {std::clamp(options.differenceFrom, 0, last),
                         std::clamp(options.differenceTo.value_or(last), 0, last)};
        if (ImGui::SliderInt2("steps (from, to)", chosen, 0, last)) {
            options.differenceFrom = std::clamp(chosen[0], 0, last);
            options.differenceTo = std::clamp(chosen[1], 0, last);
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("The difference shows density(to) - density(from).");
    }
    if (info.takesUnchanged) drawUnchangedPlaces(scene, series);
    if (scene.compositor == TemporalCompositor::Custom && options.custom) {
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
    const double narrow = 5.0;
    const double wide = 120.0;
    ImGui::SliderScalar("field of view", ImGuiDataType_Double, &camera.fovDeg, &narrow, &wide, "%.1f deg");
    if (auto* orbit = std::get_if<OrbitCamera>(&camera.pose)) {
        const double turn[2] = {-180.0, 180.0};
        const double pole[2] = {-89.0, 89.0};
        ImGui::SliderScalar("azimuth", ImGuiDataType_Double, &orbit->azimuthDeg, &turn[0], &turn[1], "%.1f deg");
        ImGui::SliderScalar("elevation", ImGuiDataType_Double, &orbit->elevationDeg, &pole[0], &pole[1], "%.1f deg");
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
