// Camera input on the volume area and the overlay drawn on the image.
#include "volume_view.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "camera_controller.h"

namespace tstyles::viewer {
namespace {

// The wheel gives no "released" moment; previews continue this long after the last notch.
constexpr std::chrono::milliseconds kWheelSettle{300};

constexpr ImGuiWindowFlags kVolumeFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoMove |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse |
    ImGuiWindowFlags_NoFocusOnAppearing;

}  // namespace

std::optional<glm::dvec2> VolumeView::handleInput(const ScreenRect& rect, glm::vec2 framebufferScale, Camera& camera,
                                                  const Bounds& bounds, glm::ivec2 frameSize, UiAnchors& anchors) {
    anchors.publish("volume", rect);
    ImGui::SetNextWindowPos({rect.min.x, rect.min.y});
    ImGui::SetNextWindowSize({rect.size().x, rect.size().y});
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0.0f, 0.0f});
    ImGui::Begin("volume", nullptr, kVolumeFlags);
    ImGui::PopStyleVar();
    ImGui::InvisibleButton("volume area", {std::max(rect.size().x, 1.0f), std::max(rect.size().y, 1.0f)},
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle |
                               ImGuiButtonFlags_MouseButtonRight);
    const ImGuiIO& io = ImGui::GetIO();
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    std::optional<glm::dvec2> pick;

    if (hovered && io.KeyCtrl && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        picking_ = true;
        const glm::vec2 local = (glm::vec2(io.MousePos.x, io.MousePos.y) - rect.min) * framebufferScale;
        pick = glm::dvec2(local);
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) picking_ = false;

    dragging_ = false;
    const glm::dvec2 delta{io.MouseDelta.x, io.MouseDelta.y};
    const bool moved = active && (delta.x != 0.0 || delta.y != 0.0);
    if (active && ImGui::IsMouseDown(ImGuiMouseButton_Left) && !picking_) {
        dragging_ = true;
        if (moved) {
            if (io.KeyShift)
                panCamera(camera, delta * glm::dvec2(framebufferScale), bounds, frameSize);
            else
                orbitCamera(camera, delta);
        }
    } else if (active && ImGui::IsMouseDown(ImGuiMouseButton_Middle)) {
        dragging_ = true;
        if (moved) panCamera(camera, delta * glm::dvec2(framebufferScale), bounds, frameSize);
    } else if (active && ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
        // Right-drag zooms: up is closer, like the wheel; 40 pixels a notch.
        dragging_ = true;
        if (moved) zoomCamera(camera, -delta.y / 40.0, bounds, frameSize);
    }
    if (hovered && io.MouseWheel != 0.0f) {
        zoomCamera(camera, double(io.MouseWheel), bounds, frameSize);
        lastWheel_ = std::chrono::steady_clock::now();
    }
    ImGui::End();
    return pick;
}

bool VolumeView::interacting(std::chrono::steady_clock::time_point now) const {
    return dragging_ || now - lastWheel_ < kWheelSettle;
}

void VolumeView::drawOverlay(const ScreenRect& rect, const VolumeOverlay& overlay, const Camera& camera,
                             const Bounds& bounds, glm::ivec2 frameSize) const {
    // Appends to the volume window of handleInput, so dialogs stay above the overlay.
    ImGui::SetNextWindowPos({rect.min.x, rect.min.y});
    ImGui::SetNextWindowSize({rect.size().x, rect.size().y});
    ImGui::Begin("volume", nullptr, kVolumeFlags);
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    drawList.PushClipRect({rect.min.x, rect.min.y}, {rect.max.x, rect.max.y});
    char text[96];
    // Bottom left, or bottom centre where the annotations' caption and scale bar sit in the corners.
    const ImVec2 corner{overlay.annotated ? 0.5f * (rect.min.x + rect.max.x) - 150.0f : rect.min.x + 8.0f,
                        rect.max.y - 24.0f};
    if (!overlay.refined) {
        // Progress of the full-quality frame: a bar and what is shown meanwhile.
        const float width = 140.0f;
        drawList.AddRectFilled({corner.x, corner.y + 4.0f}, {corner.x + width, corner.y + 14.0f},
                               IM_COL32(0, 0, 0, 150));
        drawList.AddRectFilled({corner.x, corner.y + 4.0f},
                               {corner.x + width * float(std::clamp(overlay.progress, 0.0, 1.0)), corner.y + 14.0f},
                               IM_COL32(90, 160, 255, 220));
        std::snprintf(text, sizeof text, "refining %3.0f %%  (preview at 1/%d resolution)", 100.0 * overlay.progress,
                      overlay.previewDivisor);
        drawList.AddText({corner.x + width + 8.0f, corner.y + 2.0f}, IM_COL32(220, 220, 230, 255), text);
    } else {
        std::snprintf(text, sizeof text, "full quality (%.2f s)", overlay.refinementSeconds);
        drawList.AddText({corner.x, corner.y + 2.0f}, IM_COL32(150, 150, 160, 200), text);
    }
    std::snprintf(text, sizeof text, "%.1f fps", overlay.framesPerSecond);
    const float centre = 0.5f * (rect.min.x + rect.max.x);
    drawList.AddText({overlay.annotated ? centre - 0.5f * ImGui::CalcTextSize(text).x
                                        : rect.max.x - ImGui::CalcTextSize(text).x - 8.0f,
                      rect.min.y + 6.0f},
                     IM_COL32(150, 150, 160, 200), text);
    if (overlay.note != nullptr)
        drawList.AddText({overlay.annotated ? centre - 0.5f * ImGui::CalcTextSize(overlay.note).x : rect.min.x + 8.0f,
                          rect.min.y + (overlay.annotated ? 24.0f : 6.0f)},
                         IM_COL32(255, 210, 40, 255), overlay.note);

    if (!overlay.probes.empty() && frameSize.x > 0 && frameSize.y > 0) {
        const View view = resolveView(camera, bounds, frameSize.x, frameSize.y);
        for (const ProbeMarker& marker : overlay.probes) {
            const glm::dvec4 clip = view.projectionMatrix * view.viewMatrix * glm::dvec4(marker.world, 1.0);
            if (clip.w <= 0.0) continue;
            const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
            const ImVec2 at{rect.min.x + float((ndc.x + 1.0) * 0.5) * rect.size().x,
                            rect.min.y + float((1.0 - ndc.y) * 0.5) * rect.size().y};
            const ImU32 colour = ImGui::ColorConvertFloat4ToU32({marker.colour.r, marker.colour.g, marker.colour.b, 1.0f});
            // A dark ring under the coloured one keeps the marker visible on light data.
            drawList.AddCircle(at, 7.0f, IM_COL32(0, 0, 0, 200), 0, 4.0f);
            drawList.AddCircle(at, 7.0f, colour, 0, 2.0f);
            drawList.AddCircleFilled(at, 1.5f, colour);
            const std::string number = std::to_string(marker.number);
            const ImVec2 textAt{at.x + 9.0f, at.y - 17.0f};
            drawList.AddText({textAt.x + 1.0f, textAt.y + 1.0f}, IM_COL32(0, 0, 0, 220), number.c_str());
            drawList.AddText(textAt, colour, number.c_str());
        }
    }
    drawList.PopClipRect();
    ImGui::End();
}

}  // namespace tstyles::viewer
