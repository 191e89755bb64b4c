// GLFW window and context creation, and the callbacks that queue input events.
#include "viewer_window.h"

#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "tstyles/core/errors.h"
#include "tstyles/gl/gl_api.h"
#include "tstyles/gl/headless_context.h"

namespace tstyles::viewer {
namespace {

// GLFW keeps the last error per thread; reading it here avoids a global error callback.
std::string lastGlfwError() {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    if (code == GLFW_NO_ERROR) return "no further detail from GLFW";
    return description != nullptr ? std::string(description) : "GLFW error " + std::to_string(code);
}

void* glfwProcAddress(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

}  // namespace

ViewerWindow::ViewerWindow(glm::ivec2 size, const std::string& title, bool debugContext, bool vsync) {
    if (glfwInit() != GLFW_TRUE)
        throw GlUnavailableError("cannot start GLFW (is there a display? set DISPLAY, or run under xvfb-run): " +
                                 lastGlfwError());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debugContext ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
    window_ = glfwCreateWindow(size.x, size.y, title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
        const std::string reason = lastGlfwError();
        glfwTerminate();
        throw GlUnavailableError("cannot open a window with an OpenGL 4.5 core context: " + reason);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(vsync ? 1 : 0);
    try {
        loadGlFunctions(glfwProcAddress);
    } catch (...) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw;
    }
    if (debugContext) installGlDebugOutput();
    glfwSetWindowUserPointer(window_, this);
    installCallbacks();
}

ViewerWindow::~ViewerWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

ViewerWindow& ViewerWindow::of(GLFWwindow* window) {
    return *static_cast<ViewerWindow*>(glfwGetWindowUserPointer(window));
}

void ViewerWindow::installCallbacks() {
    glfwSetCursorPosCallback(window_, [](GLFWwindow* window, double x, double y) {
        of(window).events_.push_back(MouseMoveEvent{{float(x), float(y)}});
    });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* window, int button, int action, int) {
        of(window).events_.push_back(MouseButtonEvent{button, action == GLFW_PRESS});
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* window, double x, double y) {
        of(window).events_.push_back(ScrollEvent{{float(x), float(y)}});
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int, int action, int) {
        // Repeats are not new presses: ImGui makes its own repeats from how long a key is down.
        if (action == GLFW_REPEAT) return;
        of(window).events_.push_back(KeyEvent{key, action == GLFW_PRESS});
    });
    glfwSetCharCallback(window_, [](GLFWwindow* window, unsigned int codepoint) {
        of(window).events_.push_back(CharEvent{codepoint});
    });
    glfwSetWindowFocusCallback(window_, [](GLFWwindow* window, int focused) {
        if (focused == GLFW_FALSE) of(window).events_.push_back(FocusLostEvent{});
    });
    glfwSetDropCallback(window_, [](GLFWwindow* window, int count, const char** paths) {
        for (int i = 0; i < count; ++i) of(window).dropped_.emplace_back(paths[i]);
    });
}

bool ViewerWindow::closeRequested() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void ViewerWindow::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void ViewerWindow::cancelClose() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

void ViewerWindow::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

glm::ivec2 ViewerWindow::windowSize() const {
    glm::ivec2 size;
    glfwGetWindowSize(window_, &size.x, &size.y);
    return size;
}

glm::ivec2 ViewerWindow::framebufferSize() const {
    glm::ivec2 size;
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
}

void ViewerWindow::pollEvents() { glfwPollEvents(); }

void ViewerWindow::waitEvents(double timeoutSeconds) { glfwWaitEventsTimeout(timeoutSeconds); }

std::vector<std::filesystem::path> ViewerWindow::takeDroppedFiles() { return std::exchange(dropped_, {}); }

void ViewerWindow::swapBuffers() { glfwSwapBuffers(window_); }

}  // namespace tstyles::viewer
