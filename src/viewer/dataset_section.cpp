// The dataset section (what the series is, where it sits, what it costs) and the time section.
#include <algorithm>
#include <variant>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "side_panel.h"
#include "tstyles/data/series_summary.h"

namespace tstyles::viewer {
namespace {

std::string bytesText(std::size_t bytes) {
    char text[32];
    if (bytes >= std::size_t(1) << 30)
        std::snprintf(text, sizeof text, "%.2f GiB", double(bytes) / double(std::size_t(1) << 30));
    else if (bytes >= std::size_t(1) << 20)
        std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(std::size_t(1) << 20));
    else
        std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / 1024.0);
    return text;
}

bool sameGrid(const Series& series) {
    const TimeStep& first = series.steps.front();
    if (first.structured()) return false;
    if (first.isBeam()) {
        return std::all_of(series.steps.begin(), series.steps.end(),
                           [&](const TimeStep& step) { return step.isBeam() && step.beam() == first.beam(); });
    }
    return std::all_of(series.steps.begin(), series.steps.end(), [&](const TimeStep& step) {
        return std::holds_alternative<RectilinearGrid>(step.grid) && step.dims() == first.dims() &&
               step.rectilinear().spacing == first.rectilinear().spacing &&
               step.rectilinear().axisPositions == first.rectilinear().axisPositions;
    });
}

void drawStepTable(const Series& series, const std::vector<std::string>& timeLabels) {
    constexpr ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                      ImGuiTableFlags_SizingFixedFit;
    const float height = std::min(8.0f, float(series.size()) + 1.0f) * ImGui::GetTextLineHeightWithSpacing();
    if (!ImGui::BeginTable("steps", 5, flags, {0.0f, height})) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const char* column : {"#", "time", "dims", "origin", "rot."}) ImGui::TableSetupColumn(column);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < series.size(); ++i) {
        const TimeStep& step = series.steps[i];
        const glm::ivec3 dims = step.dims();
        const AxisAngle rotation = toAxisAngle(step.placement.rotation);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%zu", i);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(timeLabels[i].c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%s%dx%dx%d", step.isBeam() ? "beam " : step.structured() ? "struct. " : "", dims.x, dims.y,
                    dims.z);
        ImGui::TableNextColumn();
        ImGui::Text("%.2f %.2f %.2f", step.placement.origin.x, step.placement.origin.y, step.placement.origin.z);
        ImGui::TableNextColumn();
        ImGui::Text("%.1f deg", rotation.angleDeg);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("axis (%.2f, %.2f, %.2f)", rotation.axis.x, rotation.axis.y, rotation.axis.z);
    }
    ImGui::EndTable();
}

}  // namespace

void drawDatasetSection(SidePanelState& state, UiAnchors&) {
    const Series& series = state.series;
    ImGui::TextWrapped("%s", series.name.c_str());
    ImGui::TextDisabled("%s", series.manifestPath.filename().string().c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", series.manifestPath.string().c_str());
    const TimeStep& first = series.steps.front();
    ImGui::Text("%zu time-steps, %s .. %s", series.size(), state.timeLabels.front().c_str(),
                state.timeLabels.back().c_str());
    const glm::ivec3 dims = first.dims();
    if (sameGrid(series) && first.isBeam())
        ImGui::Text("beam grid %dx%dx%d, range %.3g .. %.3g", dims.x, dims.y, dims.z, first.beam().minRange,
                    first.beam().maxRange);
    else if (sameGrid(series))
        ImGui::Text("grid %dx%dx%d, spacing %.3g", dims.x, dims.y, dims.z, first.rectilinear().spacing.x);
    else if (first.structured())
        ImGui::Text("structured grid %dx%dx%d", dims.x, dims.y, dims.z);
    else
        ImGui::Text("grids of different kinds or sizes");
    ImGui::Text("placement: %s", isFullyAligned(series) ? "aligned" : "moving (partial overlap)");
    ImGui::Text("values %.4g .. %.4g = density 0 .. 1", series.valueRange[0], series.valueRange[1]);
    ImGui::Text("disk %s, GPU %s", bytesText(diskBytes(series)).c_str(),
                bytesText(state.memory.seriesBytes).c_str());
    if (ImGui::IsItemHovered()) {
        const std::size_t gradientBytes = state.memory.gradientBytes;
        const std::string gradients =
            gradientBytes > 0 ? ", gradients for styles " + bytesText(gradientBytes) : std::string();
        ImGui::SetTooltip("GPU textures: series atlas %s%s, per-frame buffers %s",
                          bytesText(state.memory.seriesBytes - gradientBytes).c_str(), gradients.c_str(),
                          bytesText(state.memory.frameBytes).c_str());
    }
    // A series stored smaller or coarser than read says so where its memory is shown (--max-gpu-memory).
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    for (const std::string& change : state.memory.storageChanges) ImGui::TextWrapped("GPU: %s", change.c_str());
    ImGui::PopStyleColor();
    if (ImGui::TreeNode("Time-steps")) {
        drawStepTable(series, state.timeLabels);
        ImGui::TreePop();
    }
}

void drawTimeSection(SidePanelState& state, ViewerCommands& commands, UiAnchors& anchors) {
    TimeControl& time = state.time;
    const int last = int(state.series.size()) - 1;
    time.step = std::clamp(time.step, 0, std::max(last, 0));
    char label[48];
    std::snprintf(label, sizeof label, "%d  (%s)", time.step, state.timeLabels[std::size_t(time.step)].c_str());
    if (ImGui::SliderInt("time-step", &time.step, 0, std::max(last, 0), label)) time.solo = true;
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    anchors.publish("time-slider", ScreenRect{{min.x, min.y}, {max.x, max.y}});
    ImGui::Checkbox("show this time-step alone", &time.solo);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Plain playback for comparison: only this time-step, without the temporal compositor.\n"
                          "The scene file does not record it.");
    // The exposure: which time-steps take part in the temporal composite (saved in the scene).
    int exposure[2] = {state.scene.exposure.first, state.scene.exposure.last.value_or(last)};
    if (ImGui::DragInt2("exposure", exposure, 0.1f, 0, std::max(last, 0))) {
        exposure[0] = std::clamp(exposure[0], 0, std::max(last, 0));
        exposure[1] = std::clamp(exposure[1], exposure[0], std::max(last, 0));
        state.scene.exposure = {exposure[0], exposure[1] == last ? std::nullopt : std::optional<int>(exposure[1])};
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The first and last time-step in the image (the paper's multiple exposure)");
    if (ImGui::Button(time.playing ? "Pause" : "Play")) commands.push_back(ViewerCommand::TogglePlay);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-110.0f);
    ImGui::SliderFloat("steps/s", &time.stepsPerSecond, 0.25f, 10.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
}

}  // namespace tstyles::viewer
