// Plays a viewer test script: turns each command into input events spread over frames (a press, a
// few moves and a release for a drag, as a hand would make them) and runs the commands that talk
// to the application (save, screenshot, wait for refinement) through ScriptHost.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "input_events.h"
#include "input_script.h"

namespace tstyles::viewer {

// What a script needs from the application.
class ScriptHost {
public:
    virtual ~ScriptHost() = default;
    virtual std::optional<glm::vec2> resolveAnchor(const std::string& name,
                                                   const std::optional<glm::dvec2>& parameters) const = 0;
    virtual std::string anchorNames() const = 0;
    // The view shows the finished full-quality frame and nothing is waiting to be drawn.
    virtual bool viewRefined() const = 0;
    virtual void openFromScript(const std::filesystem::path& path) = 0;
    virtual void saveSceneFromScript(const std::filesystem::path& path) = 0;
    // Writes the probe panel's curves as CSV, as its Export does.
    virtual void exportProbesFromScript(const std::filesystem::path& path) = 0;
    // Takes the screenshot at the next refined frame (the volume area, or the whole window with
    // its panels); screenshotPending() until then.
    virtual void requestScreenshot(const std::filesystem::path& path, bool wholeWindow) = 0;
    virtual bool screenshotPending() const = 0;
    virtual void startMeasurement(const std::string& label) = 0;
    virtual void stopMeasurement() = 0;
    virtual void quitFromScript() = 0;
};

class ScriptPlayer {
public:
    using Clock = std::chrono::steady_clock;

    ScriptPlayer(std::vector<ScriptCommand> commands, std::filesystem::path origin);

    // Called once per frame, before input reaches ImGui: queues this frame's events. Throws
    // InputError (with file and line) when a command cannot be carried out.
    void advance(ScriptHost& host, InputQueue& events, Clock::time_point now);

    bool finished() const { return next_ >= commands_.size() && frames_.empty() && !waiting_; }

    // How long wait-refined and screenshot wait for the view before giving up.
    static constexpr std::chrono::seconds kRefineTimeout{180};

private:
    using Frame = std::vector<InputEvent>;

    bool continueWaiting(ScriptHost& host, Clock::time_point now);
    void start(const ScriptCommand& command, ScriptHost& host, Clock::time_point now);
    glm::vec2 resolve(const ScriptPoint& point, const ScriptHost& host, int line) const;
    void queueModifiers(int modifiers, bool pressed, Frame& frame) const;
    void queueClick(const ScriptCommand& command, glm::vec2 at);
    void queueDrag(const ScriptCommand& command, glm::vec2 from, glm::vec2 to);
    void queueKey(const ScriptCommand& command);

    std::vector<ScriptCommand> commands_;
    std::filesystem::path origin_;
    std::size_t next_ = 0;
    std::deque<Frame> frames_;  // events still to send, one entry per frame

    // A command that is waiting: for frames, a time, the refined view or a screenshot.
    bool waiting_ = false;
    const ScriptCommand* waitingFor_ = nullptr;
    int framesLeft_ = 0;
    Clock::time_point waitUntil_{};
    Clock::time_point giveUpAt_{};
};

}  // namespace tstyles::viewer
