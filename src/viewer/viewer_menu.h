// The main menu bar: File, Edit, View, with the shortcuts written next to each command.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "viewer_commands.h"

namespace tstyles::viewer {

struct MenuState {
    bool canUndo = false;
    bool canRedo = false;
    bool hasSelection = false;
    bool playing = false;
    std::vector<std::filesystem::path> recentFiles;  // newest first
};

// Draws the menu bar; chosen items go to `commands`, a recent file chosen to `openRecent`.
// Returns the bar's height.
float drawMainMenu(const MenuState& state, ViewerCommands& commands, std::optional<std::filesystem::path>& openRecent);

}  // namespace tstyles::viewer
