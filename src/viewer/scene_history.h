// Undo and redo for the viewer: whole-scene snapshots, one per finished user action (a drag is
// one action however many frames it lasts). Scenes are small, so snapshots beat command objects.
#pragma once

#include <cstddef>
#include <vector>

#include "tstyles/scene/scene.h"

namespace tstyles::viewer {

class SceneHistory {
public:
    explicit SceneHistory(Scene initial, std::size_t limit = 256);

    // Starts over from `initial` (a newly opened scene): nothing to undo or redo.
    void reset(Scene initial);

    // Makes `current` the latest state if it differs from it; the state before becomes undoable
    // and whatever could be redone is dropped. Returns whether anything was recorded.
    bool record(const Scene& current);

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    std::size_t undoDepth() const { return undo_.size(); }

    // The scene to go back (or forward) to; it becomes the latest state.
    const Scene& undo();
    const Scene& redo();

    const Scene& latest() const { return latest_; }

private:
    Scene latest_;
    std::vector<Scene> undo_;
    std::vector<Scene> redo_;
    std::size_t limit_;
};

}  // namespace tstyles::viewer
