// Snapshot undo/redo with a bounded depth.
#include "scene_history.h"

#include <stdexcept>
#include <utility>

namespace tstyles::viewer {

SceneHistory::SceneHistory(Scene initial, std::size_t limit) : latest_(std::move(initial)), limit_(limit) {}

void SceneHistory::reset(Scene initial) {
    latest_ = std::move(initial);
    undo_.clear();
    redo_.clear();
}

bool SceneHistory::record(const Scene& current) {
    if (current == latest_) return false;
    undo_.push_back(std::move(latest_));
    if (undo_.size() > limit_) undo_.erase(undo_.begin());
    latest_ = current;
    redo_.clear();
    return true;
}

const Scene& SceneHistory::undo() {
    if (undo_.empty()) throw std::logic_error("SceneHistory::undo with nothing to undo");
    redo_.push_back(std::move(latest_));
    latest_ = std::move(undo_.back());
    undo_.pop_back();
    return latest_;
}

const Scene& SceneHistory::redo() {
    if (redo_.empty()) throw std::logic_error("SceneHistory::redo with nothing to redo");
    undo_.push_back(std::move(latest_));
    latest_ = std::move(redo_.back());
    redo_.pop_back();
    return latest_;
}

}  // namespace tstyles::viewer
