// Test scripts for the viewer (`tstyles view --script FILE`): one command per line, played as
// input events through the same path real input takes. The format is documented in
// docs/viewer.md; this is its parser. Mistakes are InputErrors naming file and line.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles::viewer {

// Modifier bits a script may hold down around a click, drag or key.
inline constexpr int kModifierCtrl = 1;
inline constexpr int kModifierShift = 2;
inline constexpr int kModifierAlt = 4;

// A place on screen: window pixels, or a named anchor (its centre, or the pixel its mapping gives
// for two parameters, e.g. "tstf:3,1" is time-step 3 at opacity 1 on the TSTF canvas).
struct ScriptPoint {
    std::optional<glm::vec2> pixels;
    std::string anchor;
    std::optional<glm::dvec2> parameters;
    std::string text;  // as written, for messages
};

enum class ScriptAction {
    WaitFrames,
    WaitTime,
    WaitRefined,
    Move,
    Press,
    Release,
    Click,
    DoubleClick,
    Drag,
    Scroll,
    Key,
    Open,
    SaveScene,
    ExportProbes,
    Screenshot,
    WindowScreenshot,
    MeasureStart,
    MeasureStop,
    Quit,
};

struct ScriptCommand {
    ScriptAction action = ScriptAction::WaitFrames;
    int line = 0;
    std::optional<ScriptPoint> point;  // move, press, release, click, double-click, scroll; drag: from
    std::optional<ScriptPoint> to;     // drag
    int button = 0;                    // press, release, click, drag
    int modifiers = 0;                 // click, drag, key
    int key = 0;                       // key: a GLFW key code
    int count = 0;                     // wait: frames; drag: mouse moves between press and release
    double milliseconds = 0.0;         // wait
    double notches = 0.0;              // scroll
    std::string argument;              // open, save-scene, export-probes, screenshot: a path; measure-start: a label
};

// `origin` names the script in messages. ${NAME} in arguments is replaced by the environment
// variable NAME (an InputError if it is not set).
std::vector<ScriptCommand> parseInputScript(const std::string& text, const std::filesystem::path& origin);
std::vector<ScriptCommand> loadInputScript(const std::filesystem::path& file);

// "file:line: problem", the shape of every script message.
std::string scriptLocation(const std::filesystem::path& origin, int line);

}  // namespace tstyles::viewer
