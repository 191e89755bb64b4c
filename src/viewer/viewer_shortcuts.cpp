// Keyboard shortcuts to viewer commands (key codes are GLFW's, as the platform layer maps them).
#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "viewer_commands.h"

namespace tstyles::viewer {

void collectShortcuts(ViewerCommands& commands) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
    const bool ctrl = io.KeyCtrl;
    const bool shift = io.KeyShift;
    auto pressed = [](int key, bool repeat = false) { return ImGui::IsKeyPressed(key, repeat); };

    if (ctrl) {
        if (pressed(GLFW_KEY_Z, true)) commands.push_back(shift ? ViewerCommand::Redo : ViewerCommand::Undo);
        if (pressed(GLFW_KEY_Y, true)) commands.push_back(ViewerCommand::Redo);
        if (pressed(GLFW_KEY_G)) commands.push_back(shift ? ViewerCommand::Ungroup : ViewerCommand::Group);
        if (pressed(GLFW_KEY_A)) commands.push_back(ViewerCommand::SelectAll);
        if (pressed(GLFW_KEY_O)) commands.push_back(ViewerCommand::Open);
        if (pressed(GLFW_KEY_S)) commands.push_back(shift ? ViewerCommand::SaveAs : ViewerCommand::Save);
        if (pressed(GLFW_KEY_Q)) commands.push_back(ViewerCommand::Quit);
        if (pressed(GLFW_KEY_E)) commands.push_back(ViewerCommand::ExportMovie);
        return;
    }
    if (pressed(GLFW_KEY_DELETE) || pressed(GLFW_KEY_BACKSPACE)) commands.push_back(ViewerCommand::DeleteNodes);
    if (pressed(GLFW_KEY_LEFT, true)) commands.push_back(ViewerCommand::NudgeEarlier);
    if (pressed(GLFW_KEY_RIGHT, true)) commands.push_back(ViewerCommand::NudgeLater);
    if (pressed(GLFW_KEY_ESCAPE)) commands.push_back(ViewerCommand::ClearSelection);
    if (io.KeyAlt) return;
    if (pressed(GLFW_KEY_R)) commands.push_back(ViewerCommand::ResetCamera);
    if (pressed(GLFW_KEY_F)) commands.push_back(ViewerCommand::FitCamera);
    if (pressed(GLFW_KEY_K)) commands.push_back(ViewerCommand::AddKey);
    if (pressed(GLFW_KEY_SPACE)) commands.push_back(ViewerCommand::TogglePlay);
    if (pressed(GLFW_KEY_F12)) commands.push_back(ViewerCommand::Screenshot);
}

}  // namespace tstyles::viewer
