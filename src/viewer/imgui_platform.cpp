// Input events into ImGuiIO, the frame clock, clipboard and cursors; the GL renderer backend.
#include "imgui_platform.h"

#include <algorithm>
#include <bitset>

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "tstyles/core/errors.h"

namespace tstyles::viewer {
namespace {

const char* clipboardText(void* window) { return glfwGetClipboardString(static_cast<GLFWwindow*>(window)); }

void setClipboardText(void* window, const char* text) {
    glfwSetClipboardString(static_cast<GLFWwindow*>(window), text);
}

// ImGui 1.86 reads named keys through io.KeyMap; the viewer's key codes are GLFW's.
void mapKeys(ImGuiIO& io) {
    io.KeyMap[ImGuiKey_Tab] = GLFW_KEY_TAB;
    io.KeyMap[ImGuiKey_LeftArrow] = GLFW_KEY_LEFT;
    io.KeyMap[ImGuiKey_RightArrow] = GLFW_KEY_RIGHT;
    io.KeyMap[ImGuiKey_UpArrow] = GLFW_KEY_UP;
    io.KeyMap[ImGuiKey_DownArrow] = GLFW_KEY_DOWN;
    io.KeyMap[ImGuiKey_PageUp] = GLFW_KEY_PAGE_UP;
    io.KeyMap[ImGuiKey_PageDown] = GLFW_KEY_PAGE_DOWN;
    io.KeyMap[ImGuiKey_Home] = GLFW_KEY_HOME;
    io.KeyMap[ImGuiKey_End] = GLFW_KEY_END;
    io.KeyMap[ImGuiKey_Insert] = GLFW_KEY_INSERT;
    io.KeyMap[ImGuiKey_Delete] = GLFW_KEY_DELETE;
    io.KeyMap[ImGuiKey_Backspace] = GLFW_KEY_BACKSPACE;
    io.KeyMap[ImGuiKey_Space] = GLFW_KEY_SPACE;
    io.KeyMap[ImGuiKey_Enter] = GLFW_KEY_ENTER;
    io.KeyMap[ImGuiKey_Escape] = GLFW_KEY_ESCAPE;
    io.KeyMap[ImGuiKey_KeyPadEnter] = GLFW_KEY_KP_ENTER;
    io.KeyMap[ImGuiKey_A] = GLFW_KEY_A;
    io.KeyMap[ImGuiKey_C] = GLFW_KEY_C;
    io.KeyMap[ImGuiKey_V] = GLFW_KEY_V;
    io.KeyMap[ImGuiKey_X] = GLFW_KEY_X;
    io.KeyMap[ImGuiKey_Y] = GLFW_KEY_Y;
    io.KeyMap[ImGuiKey_Z] = GLFW_KEY_Z;
}

bool isDown(const ImGuiIO& io, int key) { return key >= 0 && key < IM_ARRAYSIZE(io.KeysDown) && io.KeysDown[key]; }

void updateModifiers(ImGuiIO& io) {
    io.KeyCtrl = isDown(io, GLFW_KEY_LEFT_CONTROL) || isDown(io, GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = isDown(io, GLFW_KEY_LEFT_SHIFT) || isDown(io, GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = isDown(io, GLFW_KEY_LEFT_ALT) || isDown(io, GLFW_KEY_RIGHT_ALT);
    io.KeySuper = isDown(io, GLFW_KEY_LEFT_SUPER) || isDown(io, GLFW_KEY_RIGHT_SUPER);
}

template <class... Handlers>
struct Overloaded : Handlers... {
    using Handlers::operator()...;
};
template <class... Handlers>
Overloaded(Handlers...) -> Overloaded<Handlers...>;

}  // namespace

ImGuiPlatform::ImGuiPlatform(GLFWwindow* window) : window_(window), lastFrame_(std::chrono::steady_clock::now()) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the layout is fixed; nothing to remember between runs
    io.BackendPlatformName = "tstyles_viewer";
    io.BackendFlags |= ImGuiBackendFlags_HasMouseCursors;
    io.GetClipboardTextFn = clipboardText;
    io.SetClipboardTextFn = setClipboardText;
    io.ClipboardUserData = window_;
    mapKeys(io);
    ImGui::StyleColorsDark();

    cursors_[ImGuiMouseCursor_Arrow] = glfwCreateStandardCursor(GLFW_ARROW_CURSOR);
    cursors_[ImGuiMouseCursor_TextInput] = glfwCreateStandardCursor(GLFW_IBEAM_CURSOR);
    cursors_[ImGuiMouseCursor_ResizeNS] = glfwCreateStandardCursor(GLFW_VRESIZE_CURSOR);
    cursors_[ImGuiMouseCursor_ResizeEW] = glfwCreateStandardCursor(GLFW_HRESIZE_CURSOR);
    cursors_[ImGuiMouseCursor_Hand] = glfwCreateStandardCursor(GLFW_HAND_CURSOR);
    // A missing cursor shape is not an error worth keeping (GLFW records one; clear it).
    glfwGetError(nullptr);

    if (!ImGui_ImplOpenGL3_Init("#version 410 core")) {
        ImGui::DestroyContext();
        throw GlUnavailableError("Dear ImGui's OpenGL 3 backend could not load its GL functions");
    }
}

ImGuiPlatform::~ImGuiPlatform() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
    for (GLFWcursor* cursor : cursors_)
        if (cursor != nullptr) glfwDestroyCursor(cursor);
}

void ImGuiPlatform::apply(InputQueue& events) {
    ImGuiIO& io = ImGui::GetIO();
    std::bitset<8> buttonsChanged;
    std::bitset<512> keysChanged;
    while (!events.empty()) {
        const bool deferred = std::visit(
            Overloaded{
                [&](const MouseMoveEvent& move) {
                    if (buttonsChanged.any()) return true;
                    io.MousePos = ImVec2(move.position.x, move.position.y);
                    return false;
                },
                [&](const MouseButtonEvent& click) {
                    if (click.button < 0 || click.button >= IM_ARRAYSIZE(io.MouseDown)) return false;
                    if (buttonsChanged.test(std::size_t(click.button))) return true;
                    io.MouseDown[click.button] = click.pressed;
                    buttonsChanged.set(std::size_t(click.button));
                    return false;
                },
                [&](const ScrollEvent& scroll) {
                    io.MouseWheelH += scroll.offset.x;
                    io.MouseWheel += scroll.offset.y;
                    return false;
                },
                [&](const KeyEvent& key) {
                    if (key.key < 0 || key.key >= IM_ARRAYSIZE(io.KeysDown)) return false;
                    if (keysChanged.test(std::size_t(key.key))) return true;
                    io.KeysDown[key.key] = key.pressed;
                    keysChanged.set(std::size_t(key.key));
                    updateModifiers(io);
                    return false;
                },
                [&](const CharEvent& character) {
                    io.AddInputCharacter(character.codepoint);
                    return false;
                },
                [&](const FocusLostEvent&) {
                    std::fill(std::begin(io.KeysDown), std::end(io.KeysDown), false);
                    std::fill(std::begin(io.MouseDown), std::end(io.MouseDown), false);
                    updateModifiers(io);
                    return false;
                },
            },
            events.front());
        if (deferred) break;
        events.pop_front();
    }
}

void ImGuiPlatform::newFrame(InputQueue& events, glm::ivec2 windowSize, glm::ivec2 framebufferSize) {
    ImGuiIO& io = ImGui::GetIO();
    apply(events);
    io.DisplaySize = ImVec2(float(windowSize.x), float(windowSize.y));
    if (windowSize.x > 0 && windowSize.y > 0)
        io.DisplayFramebufferScale =
            ImVec2(float(framebufferSize.x) / float(windowSize.x), float(framebufferSize.y) / float(windowSize.y));
    const auto now = std::chrono::steady_clock::now();
    io.DeltaTime = std::max(std::chrono::duration<float>(now - lastFrame_).count(), 1e-4f);
    lastFrame_ = now;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
}

void ImGuiPlatform::render() {
    const ImGuiMouseCursor wanted = ImGui::GetMouseCursor();
    GLFWcursor* cursor = (wanted >= 0 && wanted < ImGuiMouseCursor(cursors_.size())) ? cursors_[std::size_t(wanted)]
                                                                                       : nullptr;
    glfwSetCursor(window_, cursor != nullptr ? cursor : cursors_[ImGuiMouseCursor_Arrow]);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace tstyles::viewer
