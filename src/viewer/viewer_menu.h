// The main menu bar: File, Edit, View, with the shortcuts written next to each command.
#pragma once

#include "viewer_commands.h"

namespace tstyles::viewer {

struct MenuState {
    bool canUndo = false;
    bool canRedo = false;
    bool hasSelection = false;
    bool playing = false;
};

// Draws the menu bar; chosen items go to `commands`. Returns the bar's height.
float drawMainMenu(const MenuState& state, ViewerCommands& commands);

}  // namespace tstyles::viewer
