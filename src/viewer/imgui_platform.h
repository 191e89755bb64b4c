// Dear ImGui's platform side, written for the viewer instead of taking imgui_impl_glfw: the stock
// backend polls the mouse from GLFW each frame, which would ignore scripted input. This one feeds
// ImGui only from the InputEvent queue, so real and scripted input take the same path. It also
// owns the ImGui context and the OpenGL 3 renderer backend (which draws; it saves and restores
// the GL state it touches).
#pragma once

#include <array>
#include <chrono>

#include <glm/glm.hpp>

#include "input_events.h"

struct GLFWwindow;
struct GLFWcursor;

namespace tstyles::viewer {

class ImGuiPlatform {
public:
    // Needs the window's GL context current.
    explicit ImGuiPlatform(GLFWwindow* window);
    ~ImGuiPlatform();
    ImGuiPlatform(const ImGuiPlatform&) = delete;
    ImGuiPlatform& operator=(const ImGuiPlatform&) = delete;

    // Hands queued events to ImGui and starts its frame. A press and release of one button (or
    // key) in one frame would be a click ImGui never sees, so the later event waits for the next
    // frame; so does a move after a button change, which must land where the button was pressed.
    void newFrame(InputQueue& events, glm::ivec2 windowSize, glm::ivec2 framebufferSize);
    // Shows the mouse cursor ImGui asks for, then draws ImGui's frame into the bound framebuffer.
    void render();

private:
    void apply(InputQueue& events);

    GLFWwindow* window_;
    std::array<GLFWcursor*, 9> cursors_{};
    std::chrono::steady_clock::time_point lastFrame_;
};

}  // namespace tstyles::viewer
