// Input as the viewer receives it, from the window system or from a test script alike: both feed
// the same queue, and everything downstream (ImGui, camera, editors) cannot tell them apart. Key
// codes are GLFW's; mouse buttons are numbered as GLFW and ImGui number them (0 left, 1 right,
// 2 middle).
#pragma once

#include <deque>
#include <variant>

#include <glm/glm.hpp>

namespace tstyles::viewer {

inline constexpr int kLeftButton = 0;
inline constexpr int kRightButton = 1;
inline constexpr int kMiddleButton = 2;

struct MouseMoveEvent {
    glm::vec2 position{0.0f};  // window coordinates, origin top left
};
struct MouseButtonEvent {
    int button = kLeftButton;
    bool pressed = true;
};
struct ScrollEvent {
    glm::vec2 offset{0.0f};  // wheel notches; y up is away from the user
};
struct KeyEvent {
    int key = 0;  // GLFW_KEY_*
    bool pressed = true;
};
struct CharEvent {
    unsigned int codepoint = 0;
};
// The window lost the keyboard focus: whatever was held is released.
struct FocusLostEvent {};

using InputEvent = std::variant<MouseMoveEvent, MouseButtonEvent, ScrollEvent, KeyEvent, CharEvent, FocusLostEvent>;
using InputQueue = std::deque<InputEvent>;

}  // namespace tstyles::viewer
