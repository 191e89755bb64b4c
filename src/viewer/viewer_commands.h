// The viewer's commands, whether chosen from the menu, a toolbar or the keyboard: collected during
// a frame and carried out in one place (ViewerApp), so each has one implementation.
#pragma once

#include <vector>

namespace tstyles::viewer {

enum class ViewerCommand {
    Open,
    Save,
    SaveAs,
    Screenshot,
    Quit,
    Undo,
    Redo,
    Group,
    Ungroup,
    DeleteNodes,
    SelectAll,
    ClearSelection,
    NudgeEarlier,
    NudgeLater,
    ResetCamera,
    FitCamera,
    TogglePlay,
    AddKey,        // record the scene as the animation key at the next key frame
    ExportMovie,   // render the scene's animation into the movie file
    CancelExport,
};

using ViewerCommands = std::vector<ViewerCommand>;

// The keyboard shortcuts pressed this frame (none while a text field has the keyboard or a
// dialog is open).
void collectShortcuts(ViewerCommands& commands);

}  // namespace tstyles::viewer
