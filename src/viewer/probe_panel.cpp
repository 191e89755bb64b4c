// Drawing the probe panel with ImGui's draw list: the plot, its axes, the probe list and buttons.
#include "probe_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <imgui.h>

namespace tstyles::viewer {
namespace {

constexpr ImGuiWindowFlags kProbePanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                              ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                              ImGuiWindowFlags_NoScrollWithMouse |
                                              ImGuiWindowFlags_NoBringToFrontOnFocus;
constexpr ImU32 kProbePlotBackground = IM_COL32(28, 29, 34, 255);
constexpr ImU32 kProbeGrid = IM_COL32(255, 255, 255, 28);
constexpr ImU32 kProbeAxisText = IM_COL32(170, 172, 182, 255);
constexpr ImU32 kProbeStfBand = IM_COL32(120, 150, 255, 34);
constexpr ImU32 kProbeCurrentStep = IM_COL32(255, 255, 255, 70);
constexpr float kProbeListWidth = 300.0f;
constexpr float kValueAxisWidth = 64.0f;
constexpr float kTimeAxisHeight = 20.0f;
constexpr float kHoverRadius = 8.0f;

ImU32 packed(const glm::vec3& colour, float alpha = 1.0f) {
    const glm::vec3 clamped = glm::clamp(colour, 0.0f, 1.0f);
    return ImGui::ColorConvertFloat4ToU32({clamped.r, clamped.g, clamped.b, alpha});
}

// Where the time-steps stand across the plot, 0 to 1: by their times where those rise, else evenly.
std::vector<double> timeFractions(const Series& series) {
    const std::size_t count = series.steps.size();
    std::vector<double> fractions(count, 0.5);
    if (count < 2) return fractions;
    bool rising = true;
    for (std::size_t step = 1; step < count; ++step)
        rising = rising && series.steps[step].time > series.steps[step - 1].time;
    const double first = series.steps.front().time;
    const double span = series.steps.back().time - first;
    for (std::size_t step = 0; step < count; ++step)
        fractions[step] = rising && span > 0.0 ? (series.steps[step].time - first) / span
                                               : double(step) / double(count - 1);
    return fractions;
}

// The value axis: the curves' values and the STF's band, padded a little; one value is widened.
std::pair<double, double> valueRangeOf(const std::vector<ProbeCurve>& curves) {
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (const ProbeCurve& curve : curves)
        for (const auto& value : curve.values)
            if (value) {
                low = std::min(low, *value);
                high = std::max(high, *value);
            }
    if (!(low <= high)) return {0.0, 1.0};
    if (high - low <= 1e-12 * std::max(1.0, std::abs(high))) {
        const double half = std::max(std::abs(high) * 0.05, 0.5);
        return {low - half, high + half};
    }
    const double pad = 0.06 * (high - low);
    return {low - pad, high + pad};
}

// "Nice" tick spacing: 1, 2 or 5 times a power of ten, about `count` ticks over `span`.
double tickSpacing(double span, int count) {
    const double raw = span / std::max(count, 1);
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double factor : {1.0, 2.0, 5.0})
        if (factor * power >= raw) return factor * power;
    return 10.0 * power;
}

std::string valueText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

struct PlotFrame {
    ScreenRect area;
    std::pair<double, double> values;
    ImVec2 at(double fraction, double value) const {
        const double up = (value - values.first) / (values.second - values.first);
        return {area.min.x + float(fraction) * area.size().x, area.max.y - float(up) * area.size().y};
    }
};

void drawAxes(ImDrawList& drawList, const PlotFrame& frame, const std::vector<double>& fractions,
              const ProbePanelState& state) {
    // Value ticks across, labelled at the left.
    const double spacing = tickSpacing(frame.values.second - frame.values.first, 4);
    for (double tick = std::ceil(frame.values.first / spacing) * spacing; tick <= frame.values.second;
         tick += spacing) {
        const ImVec2 at = frame.at(0.0, tick);
        drawList.AddLine(at, {frame.area.max.x, at.y}, kProbeGrid);
        const std::string text = valueText(std::abs(tick) < 1e-9 * spacing ? 0.0 : tick);
        const ImVec2 size = ImGui::CalcTextSize(text.c_str());
        drawList.AddText({at.x - size.x - 6.0f, at.y - 0.5f * size.y}, kProbeAxisText, text.c_str());
    }
    // Time labels under the plot, from the first on, each where it clears the one before.
    float lastRight = -std::numeric_limits<float>::infinity();
    for (std::size_t step = 0; step < fractions.size(); ++step) {
        const ImVec2 at = frame.at(fractions[step], frame.values.first);
        drawList.AddLine(at, {at.x, at.y + 4.0f}, kProbeAxisText);
        if (int(step) == state.currentStep)
            drawList.AddLine({at.x, frame.area.min.y}, at, kProbeCurrentStep, 1.5f);
        const std::string& label = state.timeLabels[step];
        const ImVec2 size = ImGui::CalcTextSize(label.c_str());
        const float left = std::clamp(at.x - 0.5f * size.x, frame.area.min.x - kValueAxisWidth + 4.0f,
                                      frame.area.max.x - size.x);
        if (left < lastRight + 10.0f) continue;
        drawList.AddText({left, at.y + 5.0f}, kProbeAxisText, label.c_str());
        lastRight = left + size.x;
    }
}

// The point under the mouse, if one is within reach: which probe, which time-step.
struct HoveredPoint {
    std::size_t probe = 0;
    std::size_t step = 0;
};

std::optional<HoveredPoint> drawCurves(ImDrawList& drawList, const PlotFrame& frame,
                                       const std::vector<double>& fractions, const ProbePanelState& state) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    std::optional<HoveredPoint> hovered;
    float nearest = kHoverRadius * kHoverRadius;
    for (std::size_t probe = 0; probe < state.curves.size(); ++probe) {
        const ProbeCurve& curve = state.curves[probe];
        const ImU32 colour = packed(probeColour(probe));
        for (std::size_t step = 0; step + 1 < curve.values.size(); ++step)
            if (curve.values[step] && curve.values[step + 1])
                drawList.AddLine(frame.at(fractions[step], *curve.values[step]),
                                 frame.at(fractions[step + 1], *curve.values[step + 1]), colour, 2.0f);
        for (std::size_t step = 0; step < curve.values.size(); ++step) {
            if (!curve.values[step]) continue;
            const ImVec2 at = frame.at(fractions[step], *curve.values[step]);
            const glm::vec3 timeColour = glm::vec3(state.scene.indexTstf.atStep(int(step)).color);
            drawList.AddCircleFilled(at, 4.5f, packed(timeColour));
            drawList.AddCircle(at, 4.5f, colour, 0, 1.5f);
            const float dx = at.x - mouse.x;
            const float dy = at.y - mouse.y;
            if (dx * dx + dy * dy < nearest) {
                nearest = dx * dx + dy * dy;
                hovered = HoveredPoint{probe, step};
            }
        }
    }
    return hovered;
}

void drawPlot(const ScreenRect& area, const ProbePanelState& state, UiAnchors& anchors) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const PlotFrame frame{{{area.min.x + kValueAxisWidth, area.min.y + 4.0f}, {area.max.x - 8.0f, area.max.y - kTimeAxisHeight}},
                          valueRangeOf(state.curves)};
    if (frame.area.size().x < 20.0f || frame.area.size().y < 20.0f) return;
    const std::vector<double> fractions = timeFractions(state.series);
    drawList.AddRectFilled({frame.area.min.x, frame.area.min.y}, {frame.area.max.x, frame.area.max.y},
                           kProbePlotBackground);
    drawList.PushClipRect({frame.area.min.x, frame.area.min.y}, {frame.area.max.x, frame.area.max.y}, true);
    if (const auto shown = stfShownValues(state.scene.stf, state.series)) {
        const ImVec2 top = frame.at(0.0, std::min(shown->second, frame.values.second));
        const ImVec2 bottom = frame.at(1.0, std::max(shown->first, frame.values.first));
        if (bottom.y > top.y) drawList.AddRectFilled(top, bottom, kProbeStfBand);
    }
    drawList.PopClipRect();
    drawAxes(drawList, frame, fractions, state);
    drawList.PushClipRect({frame.area.min.x - 6.0f, frame.area.min.y - 6.0f},
                          {frame.area.max.x + 6.0f, frame.area.max.y + 6.0f}, true);
    const std::optional<HoveredPoint> hovered = drawCurves(drawList, frame, fractions, state);
    drawList.PopClipRect();
    // Scripts reach a point as "probe-plot:STEP,VALUE".
    anchors.publish("probe-plot", frame.area, [frame, fractions](glm::dvec2 parameters) {
        const std::size_t step = std::size_t(std::clamp(parameters.x, 0.0, double(fractions.size() - 1)));
        const ImVec2 at = frame.at(fractions[step], parameters.y);
        return glm::vec2(at.x, at.y);
    });
    if (hovered && ImGui::IsWindowHovered()) {
        const ProbeCurve& curve = state.curves[hovered->probe];
        const std::string unit = state.series.valueUnit.empty() ? "" : " " + state.series.valueUnit;
        ImGui::BeginTooltip();
        ImGui::Text("probe %zu at (%.5g, %.5g, %.5g)", hovered->probe + 1, curve.file.x, curve.file.y, curve.file.z);
        ImGui::Text("%s: %s%s", state.timeLabels[hovered->step].c_str(),
                    storedValueText(*curve.values[hovered->step]).c_str(), unit.c_str());
        ImGui::EndTooltip();
    }
}

// The list beside the plot: a line per probe with its colour, its place and a remove button.
void drawProbeList(const ProbePanelState& state, ProbePanelRequests& requests, UiAnchors& anchors) {
    for (std::size_t probe = 0; probe < state.curves.size(); ++probe) {
        ImGui::PushID(int(probe));
        const ImVec2 start = ImGui::GetCursorScreenPos();
        const float side = ImGui::GetTextLineHeight();
        ImGui::GetWindowDrawList()->AddRectFilled({start.x, start.y + 2.0f}, {start.x + side, start.y + side + 2.0f},
                                                  packed(probeColour(probe)));
        ImGui::Dummy({side, side});
        ImGui::SameLine();
        if (ImGui::SmallButton("x")) requests.remove = probe;
        // Scripts remove probe N with "probe-remove-N".
        anchors.publish("probe-remove-" + std::to_string(probe + 1),
                        {{ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y},
                         {ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y}});
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this probe (ctrl+z brings it back)");
        ImGui::SameLine();
        const ProbeCurve& curve = state.curves[probe];
        const bool any = std::any_of(curve.values.begin(), curve.values.end(),
                                     [](const std::optional<double>& value) { return value.has_value(); });
        char place[96];
        std::snprintf(place, sizeof place, "%zu  (%.5g, %.5g, %.5g)", probe + 1, curve.file.x, curve.file.y,
                      curve.file.z);
        ImGui::TextUnformatted(place);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", placeText(curve.file).c_str());
        if (!any) {
            ImGui::SameLine();
            ImGui::TextDisabled("(outside the data)");
        }
        ImGui::PopID();
    }
}

}  // namespace

std::optional<std::pair<double, double>> stfShownValues(const Stf& stf, const Series& series) {
    const std::vector<OpacityNode>& nodes = stf.curve.opacity;
    const auto shows = [](const OpacityNode& node) { return node.opacity > 0.0; };
    const auto first = std::find_if(nodes.begin(), nodes.end(), shows);
    if (first == nodes.end()) return std::nullopt;
    const auto last = std::find_if(nodes.rbegin(), nodes.rend(), shows);
    // The curve is linear between nodes and holds its end values beyond them: it shows from the
    // node before the first that shows (or from 0), to the node after the last (or to 1).
    const double lowest = first == nodes.begin() ? 0.0 : std::prev(first)->at;
    const double highest = last == nodes.rbegin() ? 1.0 : std::prev(last)->at;
    const double low = series.valueRange[0];
    const double span = series.valueRange[1] - series.valueRange[0];
    return std::make_pair(low + std::clamp(lowest, 0.0, 1.0) * span, low + std::clamp(highest, 0.0, 1.0) * span);
}

ProbePanelRequests drawProbePanel(const ScreenRect& rect, const ProbePanelState& state, UiAnchors& anchors) {
    ProbePanelRequests requests;
    ImGui::SetNextWindowPos({rect.min.x, rect.min.y});
    ImGui::SetNextWindowSize({rect.size().x, rect.size().y});
    const std::string unit = state.series.valueUnit.empty() ? "" : " (" + state.series.valueUnit + ")";
    const std::string title = "Probes: " + state.series.name + unit + " over time###probes";
    if (ImGui::Begin(title.c_str(), nullptr, kProbePanelFlags)) {
        anchors.publish("probes", rect);
        const ImVec2 start = ImGui::GetCursorScreenPos();
        const ImVec2 available = ImGui::GetContentRegionAvail();
        const float listWidth = std::min(kProbeListWidth, 0.4f * available.x);
        drawPlot({{start.x, start.y}, {start.x + available.x - listWidth, start.y + available.y}}, state, anchors);
        ImGui::SetCursorScreenPos({start.x + available.x - listWidth + 8.0f, start.y});
        ImGui::BeginGroup();
        if (ImGui::Button("Export CSV...")) requests.exportCsv = true;
        ImGui::SameLine();
        if (ImGui::Button("Clear")) requests.clear = true;
        drawProbeList(state, requests, anchors);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("Ctrl+click the picture to add a probe; hover a point for its value.");
        ImGui::PopTextWrapPos();
        ImGui::EndGroup();
    }
    ImGui::End();
    return requests;
}

}  // namespace tstyles::viewer
