// The viewer's sliders for scene keys (key_slider.h) inside an ImGui frame without a window: a slider
// shows the key's range, or a part of it, and refuses one reaching past what the reader takes.
#include <stdexcept>

#include <gtest/gtest.h>
#include <imgui.h>

#include "viewer/key_slider.h"

namespace tstyles::viewer {
namespace {

// An ImGui context with one frame begun: enough to lay out widgets without drawing them.
class ImGuiFrame {
public:
    ImGuiFrame() {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(640.0f, 480.0f);
        unsigned char* pixels = nullptr;
        int width = 0;
        int height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
        ImGui::NewFrame();
        ImGui::Begin("keys");
    }
    ~ImGuiFrame() {
        ImGui::End();
        ImGui::EndFrame();
        ImGui::DestroyContext();
    }
    ImGuiFrame(const ImGuiFrame&) = delete;
    ImGuiFrame& operator=(const ImGuiFrame&) = delete;
};

TEST(KeySlider, ShowsAPartOfTheKeysRangeAndRefusesMore) {
    ImGuiFrame frame;
    double termination = 0.99;
    EXPECT_NO_THROW(
        drawKeySlider({"termination", "raycast.termination", "%.3f", false, Interval{0.05, 1.0}}, termination));
    EXPECT_EQ(termination, 0.99) << "drawing without input changes nothing";
    // 0 is outside (0, 1]: the window must not offer what a scene file may not hold.
    EXPECT_THROW(drawKeySlider({"termination", "raycast.termination", "%.3f", false, Interval{0.0, 1.0}}, termination),
                 std::logic_error);
    // An open range needs a shown part: raycast.step takes any number > 0.
    double step = 0.5;
    EXPECT_THROW(drawKeySlider({"step", "raycast.step"}, step), std::logic_error);
    EXPECT_NO_THROW(drawKeySlider({"step", "raycast.step", "%.3f", true, Interval{0.01, 10.0}}, step));
    // A key the table does not have, or one that holds no number, is a programming error.
    EXPECT_THROW(drawKeySlider({"x", "raycast.steps"}, step), std::logic_error);
    EXPECT_THROW(drawKeySlider({"x", "final"}, step), std::logic_error);
}

}  // namespace
}  // namespace tstyles::viewer
