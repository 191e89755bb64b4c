// Parsing viewer test scripts: tokens, points, buttons, key combinations and the commands.
#include "input_script.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "input_events.h"
#include "tstyles/core/errors.h"

namespace tstyles::viewer {
namespace {

constexpr int kDefaultDragMoves = 12;

class LineParser {
public:
    LineParser(const std::filesystem::path& origin, int line) : origin_(origin), line_(line) {}

    [[noreturn]] void fail(const std::string& problem) const {
        throw InputError(scriptLocation(origin_, line_) + " " + problem);
    }

    // Splits on blanks; "double quotes" keep blanks; a token starting with # ends the line.
    std::vector<std::string> tokenize(const std::string& text) const {
        std::vector<std::string> tokens;
        std::size_t i = 0;
        while (i < text.size()) {
            while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
            if (i >= text.size() || text[i] == '#') break;
            std::string token;
            if (text[i] == '"') {
                const std::size_t close = text.find('"', i + 1);
                if (close == std::string::npos) fail("unterminated \"quoted\" argument");
                token = text.substr(i + 1, close - i - 1);
                i = close + 1;
            } else {
                while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) token += text[i++];
            }
            tokens.push_back(expandEnvironment(token));
        }
        return tokens;
    }

    double number(const std::string& text, const std::string& what) const {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
            fail("expected a number for " + what + ", got \"" + text + "\"");
        return value;
    }

    int count(const std::string& text, const std::string& what) const {
        const double value = number(text, what);
        if (value < 0.0 || value != double(int(value))) fail(what + " must be a whole number >= 0, got \"" + text + "\"");
        return int(value);
    }

    glm::dvec2 pair(const std::string& text, const std::string& what) const {
        const std::size_t comma = text.find(',');
        if (comma == std::string::npos) fail("expected two numbers \"A,B\" for " + what + ", got \"" + text + "\"");
        return {number(text.substr(0, comma), what), number(text.substr(comma + 1), what)};
    }

    ScriptPoint point(const std::string& text) const {
        ScriptPoint point;
        point.text = text;
        if (!text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-')) {
            point.pixels = glm::vec2(pair(text, "a pixel position"));
            return point;
        }
        const std::size_t colon = text.find(':');
        point.anchor = text.substr(0, colon);
        if (point.anchor.empty()) fail("expected a point (X,Y or ANCHOR or ANCHOR:U,V), got \"" + text + "\"");
        if (colon != std::string::npos) point.parameters = pair(text.substr(colon + 1), "anchor parameters");
        return point;
    }

    // "ctrl+shift+x": the modifiers and what is left after them.
    std::pair<int, std::string> modifiersAndName(const std::string& text) const {
        int modifiers = 0;
        std::string rest = text;
        static const std::map<std::string, int> names = {
            {"ctrl", kModifierCtrl}, {"shift", kModifierShift}, {"alt", kModifierAlt}};
        for (std::size_t plus = rest.find('+'); plus != std::string::npos && plus + 1 < rest.size();
             plus = rest.find('+')) {
            const auto found = names.find(rest.substr(0, plus));
            if (found == names.end()) fail("unknown modifier \"" + rest.substr(0, plus) + "\" (ctrl, shift, alt)");
            modifiers |= found->second;
            rest = rest.substr(plus + 1);
        }
        return {modifiers, rest};
    }

    std::pair<int, int> button(const std::string& text) const {
        const auto [modifiers, name] = modifiersAndName(text);
        if (name == "left") return {kLeftButton, modifiers};
        if (name == "right") return {kRightButton, modifiers};
        if (name == "middle") return {kMiddleButton, modifiers};
        fail("unknown mouse button \"" + name + "\" (left, middle, right, with ctrl+, shift+, alt+ before it)");
    }

    std::pair<int, int> keyCombination(const std::string& text) const {
        const auto [modifiers, name] = modifiersAndName(text);
        if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0])))
            return {GLFW_KEY_A + (std::tolower(static_cast<unsigned char>(name[0])) - 'a'), modifiers};
        if (name.size() == 1 && std::isdigit(static_cast<unsigned char>(name[0])))
            return {GLFW_KEY_0 + (name[0] - '0'), modifiers};
        static const std::map<std::string, int> keys = {
            {"left", GLFW_KEY_LEFT},       {"right", GLFW_KEY_RIGHT},   {"up", GLFW_KEY_UP},
            {"down", GLFW_KEY_DOWN},       {"delete", GLFW_KEY_DELETE}, {"backspace", GLFW_KEY_BACKSPACE},
            {"escape", GLFW_KEY_ESCAPE},   {"enter", GLFW_KEY_ENTER},   {"space", GLFW_KEY_SPACE},
            {"tab", GLFW_KEY_TAB},         {"home", GLFW_KEY_HOME},     {"end", GLFW_KEY_END},
            {"pageup", GLFW_KEY_PAGE_UP},  {"pagedown", GLFW_KEY_PAGE_DOWN}};
        const auto found = keys.find(name);
        if (found == keys.end())
            fail("unknown key \"" + name + "\" (a-z, 0-9, left, right, up, down, delete, backspace, escape, enter, "
                                           "space, tab, home, end, pageup, pagedown)");
        return {found->second, modifiers};
    }

private:
    std::string expandEnvironment(const std::string& token) const {
        std::string result;
        std::size_t i = 0;
        while (i < token.size()) {
            const std::size_t open = token.find("${", i);
            if (open == std::string::npos) break;
            const std::size_t close = token.find('}', open);
            if (close == std::string::npos) fail("unterminated ${NAME} in \"" + token + "\"");
            const std::string name = token.substr(open + 2, close - open - 2);
            const char* value = std::getenv(name.c_str());
            if (value == nullptr) fail("the environment variable " + name + " is not set");
            result += token.substr(i, open - i) + value;
            i = close + 1;
        }
        return result + token.substr(i);
    }

    const std::filesystem::path& origin_;
    int line_;
};

void expectArguments(const LineParser& parser, const std::vector<std::string>& tokens, std::size_t least,
                     std::size_t most, const std::string& usage) {
    const std::size_t given = tokens.size() - 1;
    if (given < least || given > most) parser.fail("usage: " + usage);
}

ScriptCommand parseWait(const LineParser& parser, const std::vector<std::string>& tokens, ScriptCommand command) {
    expectArguments(parser, tokens, 1, 1, "wait FRAMES | wait 500ms | wait 2s");
    const std::string& amount = tokens[1];
    auto endsWith = [&](const std::string& suffix) {
        return amount.size() > suffix.size() && amount.compare(amount.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (endsWith("ms")) {
        command.action = ScriptAction::WaitTime;
        command.milliseconds = parser.number(amount.substr(0, amount.size() - 2), "wait");
    } else if (endsWith("s")) {
        command.action = ScriptAction::WaitTime;
        command.milliseconds = 1000.0 * parser.number(amount.substr(0, amount.size() - 1), "wait");
    } else {
        command.action = ScriptAction::WaitFrames;
        command.count = parser.count(amount, "wait");
    }
    return command;
}

ScriptCommand parseLine(const LineParser& parser, const std::vector<std::string>& tokens, int line) {
    ScriptCommand command;
    command.line = line;
    const std::string& verb = tokens[0];
    if (verb == "wait") return parseWait(parser, tokens, command);
    if (verb == "wait-refined") {
        expectArguments(parser, tokens, 0, 0, "wait-refined");
        command.action = ScriptAction::WaitRefined;
    } else if (verb == "move") {
        expectArguments(parser, tokens, 1, 1, "move POINT");
        command.action = ScriptAction::Move;
        command.point = parser.point(tokens[1]);
    } else if (verb == "press" || verb == "release") {
        expectArguments(parser, tokens, 1, 2, verb + " BUTTON [POINT]");
        command.action = verb == "press" ? ScriptAction::Press : ScriptAction::Release;
        std::tie(command.button, command.modifiers) = parser.button(tokens[1]);
        if (command.modifiers != 0) parser.fail("press and release take a plain button; hold modifiers with key");
        if (tokens.size() > 2) command.point = parser.point(tokens[2]);
    } else if (verb == "click") {
        expectArguments(parser, tokens, 2, 2, "click BUTTON POINT");
        command.action = ScriptAction::Click;
        std::tie(command.button, command.modifiers) = parser.button(tokens[1]);
        command.point = parser.point(tokens[2]);
    } else if (verb == "double-click") {
        expectArguments(parser, tokens, 1, 1, "double-click POINT");
        command.action = ScriptAction::DoubleClick;
        command.point = parser.point(tokens[1]);
    } else if (verb == "drag") {
        expectArguments(parser, tokens, 3, 4, "drag BUTTON FROM TO [MOVES]");
        command.action = ScriptAction::Drag;
        std::tie(command.button, command.modifiers) = parser.button(tokens[1]);
        command.point = parser.point(tokens[2]);
        command.to = parser.point(tokens[3]);
        command.count = tokens.size() > 4 ? std::max(parser.count(tokens[4], "drag moves"), 1) : kDefaultDragMoves;
    } else if (verb == "scroll") {
        expectArguments(parser, tokens, 1, 2, "scroll NOTCHES [POINT]");
        command.action = ScriptAction::Scroll;
        command.notches = parser.number(tokens[1], "scroll");
        if (tokens.size() > 2) command.point = parser.point(tokens[2]);
    } else if (verb == "key") {
        expectArguments(parser, tokens, 1, 1, "key [ctrl+][shift+][alt+]KEY");
        command.action = ScriptAction::Key;
        std::tie(command.key, command.modifiers) = parser.keyCombination(tokens[1]);
    } else if (verb == "open" || verb == "save-scene" || verb == "export-probes" || verb == "screenshot" ||
               verb == "screenshot-window") {
        expectArguments(parser, tokens, 1, 1, verb + " PATH");
        command.action = verb == "open"              ? ScriptAction::Open
                         : verb == "save-scene"      ? ScriptAction::SaveScene
                         : verb == "export-probes"   ? ScriptAction::ExportProbes
                         : verb == "screenshot"      ? ScriptAction::Screenshot
                                                     : ScriptAction::WindowScreenshot;
        command.argument = tokens[1];
    } else if (verb == "measure-start") {
        expectArguments(parser, tokens, 1, 1, "measure-start LABEL");
        command.action = ScriptAction::MeasureStart;
        command.argument = tokens[1];
    } else if (verb == "measure-stop") {
        expectArguments(parser, tokens, 0, 0, "measure-stop");
        command.action = ScriptAction::MeasureStop;
    } else if (verb == "quit") {
        expectArguments(parser, tokens, 0, 0, "quit");
        command.action = ScriptAction::Quit;
    } else {
        parser.fail("unknown command \"" + verb +
                    "\" (wait, wait-refined, move, press, release, click, double-click, drag, scroll, key, open, "
                    "save-scene, export-probes, screenshot, screenshot-window, measure-start, measure-stop, quit)");
    }
    return command;
}

}  // namespace

std::string scriptLocation(const std::filesystem::path& origin, int line) {
    return origin.string() + ":" + std::to_string(line) + ":";
}

std::vector<ScriptCommand> parseInputScript(const std::string& text, const std::filesystem::path& origin) {
    std::vector<ScriptCommand> commands;
    std::istringstream lines(text);
    std::string lineText;
    int line = 0;
    while (std::getline(lines, lineText)) {
        ++line;
        const LineParser parser(origin, line);
        const std::vector<std::string> tokens = parser.tokenize(lineText);
        if (tokens.empty()) continue;
        commands.push_back(parseLine(parser, tokens, line));
    }
    return commands;
}

std::vector<ScriptCommand> loadInputScript(const std::filesystem::path& file) {
    std::ifstream stream(file);
    if (!stream) throwInputError(file, "", "cannot read the script");
    std::stringstream text;
    text << stream.rdbuf();
    return parseInputScript(text.str(), file);
}

}  // namespace tstyles::viewer
