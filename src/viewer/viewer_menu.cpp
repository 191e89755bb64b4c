// Menu items for the viewer commands.
#include "viewer_menu.h"

#include <imgui.h>

namespace tstyles::viewer {

float drawMainMenu(const MenuState& state, ViewerCommands& commands, std::optional<std::filesystem::path>& openRecent) {
    if (!ImGui::BeginMainMenuBar()) return 0.0f;
    auto item = [&](const char* label, const char* shortcut, ViewerCommand command, bool enabled = true) {
        if (ImGui::MenuItem(label, shortcut, false, enabled)) commands.push_back(command);
    };
    if (ImGui::BeginMenu("File")) {
        item("Open scene or dataset...", "Ctrl+O", ViewerCommand::Open);
        if (ImGui::BeginMenu("Open recent", !state.recentFiles.empty())) {
            for (const auto& path : state.recentFiles)
                if (ImGui::MenuItem(path.string().c_str())) openRecent = path;
            ImGui::EndMenu();
        }
        item("Save scene", "Ctrl+S", ViewerCommand::Save);
        item("Save scene as...", "Ctrl+Shift+S", ViewerCommand::SaveAs);
        item("Save screenshot (PNG)...", "F12", ViewerCommand::Screenshot);
        ImGui::Separator();
        item("Quit", "Ctrl+Q", ViewerCommand::Quit);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        item("Undo", "Ctrl+Z", ViewerCommand::Undo, state.canUndo);
        item("Redo", "Ctrl+Y", ViewerCommand::Redo, state.canRedo);
        ImGui::Separator();
        item("Group selected nodes", "Ctrl+G", ViewerCommand::Group, state.hasSelection);
        item("Ungroup selected nodes", "Ctrl+Shift+G", ViewerCommand::Ungroup, state.hasSelection);
        item("Delete selected nodes", "Del", ViewerCommand::DeleteNodes, state.hasSelection);
        item("Move selection one time-step earlier", "Left", ViewerCommand::NudgeEarlier, state.hasSelection);
        item("Move selection one time-step later", "Right", ViewerCommand::NudgeLater, state.hasSelection);
        item("Select all nodes", "Ctrl+A", ViewerCommand::SelectAll);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        item("Reset camera", "R", ViewerCommand::ResetCamera);
        item("Fit camera to data", "F", ViewerCommand::FitCamera);
        item(state.playing ? "Pause playback" : "Play time-steps", "Space", ViewerCommand::TogglePlay);
        ImGui::EndMenu();
    }
    const float height = ImGui::GetWindowSize().y;
    ImGui::EndMainMenuBar();
    return height;
}

}  // namespace tstyles::viewer
