// Script commands as frames of input events, and the waits between them.
#include "script_player.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "tstyles/core/errors.h"

namespace tstyles::viewer {

ScriptPlayer::ScriptPlayer(std::vector<ScriptCommand> commands, std::filesystem::path origin)
    : commands_(std::move(commands)), origin_(std::move(origin)) {}

void ScriptPlayer::advance(ScriptHost& host, InputQueue& events, Clock::time_point now) {
    if (frames_.empty() && !(waiting_ && continueWaiting(host, now))) {
        waiting_ = false;
        if (next_ < commands_.size()) start(commands_[next_++], host, now);
    }
    if (!frames_.empty()) {
        for (const InputEvent& event : frames_.front()) events.push_back(event);
        frames_.pop_front();
    }
}

bool ScriptPlayer::continueWaiting(ScriptHost& host, Clock::time_point now) {
    const ScriptCommand& command = *waitingFor_;
    switch (command.action) {
        case ScriptAction::WaitFrames:
            return framesLeft_-- > 0;
        case ScriptAction::WaitTime:
            return now < waitUntil_;
        case ScriptAction::WaitRefined:
        case ScriptAction::Screenshot:
        case ScriptAction::WindowScreenshot: {
            const bool done =
                command.action == ScriptAction::WaitRefined ? host.viewRefined() : !host.screenshotPending();
            if (done) return false;
            if (now > giveUpAt_)
                throw InputError(scriptLocation(origin_, command.line) + " the view did not finish refining within " +
                                 std::to_string(kRefineTimeout.count()) + " s");
            return true;
        }
        default:
            return false;
    }
}

void ScriptPlayer::start(const ScriptCommand& command, ScriptHost& host, Clock::time_point now) {
    auto wait = [&] {
        waiting_ = true;
        waitingFor_ = &command;
        giveUpAt_ = now + kRefineTimeout;
    };
    switch (command.action) {
        case ScriptAction::WaitFrames:
            framesLeft_ = command.count;
            wait();
            break;
        case ScriptAction::WaitTime:
            waitUntil_ = now + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double, std::milli>(command.milliseconds));
            wait();
            break;
        case ScriptAction::WaitRefined:
            wait();
            break;
        case ScriptAction::Move:
            frames_.push_back({MouseMoveEvent{resolve(*command.point, host, command.line)}});
            break;
        case ScriptAction::Press:
        case ScriptAction::Release: {
            if (command.point) frames_.push_back({MouseMoveEvent{resolve(*command.point, host, command.line)}});
            frames_.push_back({MouseButtonEvent{command.button, command.action == ScriptAction::Press}});
            break;
        }
        case ScriptAction::Click:
            queueClick(command, resolve(*command.point, host, command.line));
            break;
        case ScriptAction::DoubleClick: {
            const glm::vec2 at = resolve(*command.point, host, command.line);
            frames_.push_back({MouseMoveEvent{at}});
            for (int click = 0; click < 2; ++click) {
                frames_.push_back({MouseButtonEvent{kLeftButton, true}});
                frames_.push_back({MouseButtonEvent{kLeftButton, false}});
            }
            break;
        }
        case ScriptAction::Drag:
            queueDrag(command, resolve(*command.point, host, command.line), resolve(*command.to, host, command.line));
            break;
        case ScriptAction::Scroll:
            if (command.point) frames_.push_back({MouseMoveEvent{resolve(*command.point, host, command.line)}});
            frames_.push_back({ScrollEvent{{0.0f, float(command.notches)}}});
            break;
        case ScriptAction::Key:
            queueKey(command);
            break;
        case ScriptAction::Open:
            host.openFromScript(command.argument);
            break;
        case ScriptAction::SaveScene:
            host.saveSceneFromScript(command.argument);
            break;
        case ScriptAction::ExportProbes:
            host.exportProbesFromScript(command.argument);
            break;
        case ScriptAction::Screenshot:
        case ScriptAction::WindowScreenshot:
            host.requestScreenshot(command.argument, command.action == ScriptAction::WindowScreenshot);
            wait();
            break;
        case ScriptAction::MeasureStart:
            host.startMeasurement(command.argument);
            break;
        case ScriptAction::MeasureStop:
            host.stopMeasurement();
            break;
        case ScriptAction::Quit:
            host.quitFromScript();
            break;
    }
}

glm::vec2 ScriptPlayer::resolve(const ScriptPoint& point, const ScriptHost& host, int line) const {
    if (point.pixels) return *point.pixels;
    if (auto pixel = host.resolveAnchor(point.anchor, point.parameters)) return *pixel;
    throw InputError(scriptLocation(origin_, line) + " no anchor \"" + point.anchor +
                     "\" on screen; anchors now: " + host.anchorNames());
}

void ScriptPlayer::queueModifiers(int modifiers, bool pressed, Frame& frame) const {
    if (modifiers & kModifierCtrl) frame.push_back(KeyEvent{GLFW_KEY_LEFT_CONTROL, pressed});
    if (modifiers & kModifierShift) frame.push_back(KeyEvent{GLFW_KEY_LEFT_SHIFT, pressed});
    if (modifiers & kModifierAlt) frame.push_back(KeyEvent{GLFW_KEY_LEFT_ALT, pressed});
}

// Three frames: go there (modifiers down), press, release (modifiers up). ImGui sees one button
// change per frame, as with a real click.
void ScriptPlayer::queueClick(const ScriptCommand& command, glm::vec2 at) {
    Frame arrive{MouseMoveEvent{at}};
    queueModifiers(command.modifiers, true, arrive);
    frames_.push_back(arrive);
    frames_.push_back({MouseButtonEvent{command.button, true}});
    Frame leave{MouseButtonEvent{command.button, false}};
    queueModifiers(command.modifiers, false, leave);
    frames_.push_back(leave);
}

void ScriptPlayer::queueDrag(const ScriptCommand& command, glm::vec2 from, glm::vec2 to) {
    Frame arrive{MouseMoveEvent{from}};
    queueModifiers(command.modifiers, true, arrive);
    frames_.push_back(arrive);
    frames_.push_back({MouseButtonEvent{command.button, true}});
    for (int move = 1; move <= command.count; ++move)
        frames_.push_back({MouseMoveEvent{glm::mix(from, to, float(move) / float(command.count))}});
    Frame leave{MouseButtonEvent{command.button, false}};
    queueModifiers(command.modifiers, false, leave);
    frames_.push_back(leave);
}

void ScriptPlayer::queueKey(const ScriptCommand& command) {
    Frame down;
    queueModifiers(command.modifiers, true, down);
    down.push_back(KeyEvent{command.key, true});
    frames_.push_back(down);
    Frame up{KeyEvent{command.key, false}};
    queueModifiers(command.modifiers, false, up);
    frames_.push_back(up);
}

}  // namespace tstyles::viewer
