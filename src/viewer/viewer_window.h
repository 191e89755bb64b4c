// The viewer's window: GLFW set up and torn down, an OpenGL 4.5 core context made current with the
// GL entry points loaded, and the window's input turned into InputEvents. Nothing else in the
// viewer talks to GLFW's event callbacks.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "input_events.h"

struct GLFWwindow;

namespace tstyles::viewer {

class ViewerWindow {
public:
    // Opens the window or throws GlUnavailableError saying why (no display, no OpenGL 4.5).
    ViewerWindow(glm::ivec2 size, const std::string& title, bool debugContext, bool vsync);
    ~ViewerWindow();
    // Callbacks hold a pointer to this object: it stays where it was made.
    ViewerWindow(const ViewerWindow&) = delete;
    ViewerWindow& operator=(const ViewerWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool closeRequested() const;
    void requestClose();
    // The user asked to close, but the application wants to ask first.
    void cancelClose();
    void setTitle(const std::string& title);

    glm::ivec2 windowSize() const;
    glm::ivec2 framebufferSize() const;

    // Collects pending window-system events into events(); with a timeout, sleeps until one
    // arrives or the time is up (an idle viewer should not spin).
    void pollEvents();
    void waitEvents(double timeoutSeconds);
    InputQueue& events() { return events_; }
    // Files dropped on the window since the last call.
    std::vector<std::filesystem::path> takeDroppedFiles();

    void swapBuffers();

private:
    static ViewerWindow& of(GLFWwindow* window);
    void installCallbacks();

    GLFWwindow* window_ = nullptr;
    InputQueue events_;
    std::vector<std::filesystem::path> dropped_;
};

}  // namespace tstyles::viewer
