// The viewer's test-script format: every command parses to what docs/viewer.md says, and mistakes
// name the file and line.
#include <gtest/gtest.h>

#include <cstdlib>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "tstyles/core/errors.h"
#include "viewer/input_events.h"
#include "viewer/input_script.h"

namespace {

using namespace tstyles::viewer;

TEST(InputScript, ParsesEveryCommand) {
    const std::string text = R"(# a comment, then a blank line

wait 10
wait 250ms
wait 1.5s
wait-refined
move 12,34
press middle volume
release middle
click ctrl+left volume:0.5,0.25   # pick
double-click stf:0.3,0.4
drag shift+left tstf:3,1 tstf:6,1 7
scroll -2 volume
key ctrl+shift+g
key delete
open "some folder/scene.json"
save-scene out.json
screenshot shot.png
screenshot-window window.png
measure-start orbit
measure-stop
export-probes probes.csv
quit
)";
    const std::vector<ScriptCommand> commands = parseInputScript(text, "test.txt");
    ASSERT_EQ(commands.size(), 21u);
    EXPECT_EQ(commands[0].action, ScriptAction::WaitFrames);
    EXPECT_EQ(commands[0].count, 10);
    EXPECT_EQ(commands[0].line, 3);
    EXPECT_EQ(commands[1].action, ScriptAction::WaitTime);
    EXPECT_EQ(commands[1].milliseconds, 250.0);
    EXPECT_EQ(commands[2].milliseconds, 1500.0);
    EXPECT_EQ(commands[3].action, ScriptAction::WaitRefined);
    EXPECT_EQ(commands[4].point->pixels, glm::vec2(12.0f, 34.0f));
    EXPECT_EQ(commands[5].button, kMiddleButton);
    EXPECT_EQ(commands[5].point->anchor, "volume");
    EXPECT_FALSE(commands[5].point->parameters.has_value());
    EXPECT_FALSE(commands[6].point.has_value());
    EXPECT_EQ(commands[7].action, ScriptAction::Click);
    EXPECT_EQ(commands[7].modifiers, kModifierCtrl);
    EXPECT_EQ(commands[7].point->parameters, glm::dvec2(0.5, 0.25));
    EXPECT_EQ(commands[8].action, ScriptAction::DoubleClick);
    EXPECT_EQ(commands[9].action, ScriptAction::Drag);
    EXPECT_EQ(commands[9].modifiers, kModifierShift);
    EXPECT_EQ(commands[9].to->anchor, "tstf");
    EXPECT_EQ(commands[9].to->parameters, glm::dvec2(6.0, 1.0));
    EXPECT_EQ(commands[9].count, 7);
    EXPECT_EQ(commands[10].notches, -2.0);
    EXPECT_EQ(commands[11].key, GLFW_KEY_G);
    EXPECT_EQ(commands[11].modifiers, kModifierCtrl | kModifierShift);
    EXPECT_EQ(commands[12].key, GLFW_KEY_DELETE);
    EXPECT_EQ(commands[13].argument, "some folder/scene.json");
    EXPECT_EQ(commands[14].action, ScriptAction::SaveScene);
    EXPECT_EQ(commands[15].action, ScriptAction::Screenshot);
    EXPECT_EQ(commands[16].action, ScriptAction::WindowScreenshot);
    EXPECT_EQ(commands[17].argument, "orbit");
    EXPECT_EQ(commands[19].action, ScriptAction::ExportProbes);
    EXPECT_EQ(commands[19].argument, "probes.csv");
    EXPECT_EQ(commands[20].action, ScriptAction::Quit);
}

TEST(InputScript, ExpandsEnvironmentVariables) {
    setenv("TSTYLES_SCRIPT_TEST_DIR", "/tmp/out", 1);
    const auto commands = parseInputScript("save-scene ${TSTYLES_SCRIPT_TEST_DIR}/a.json\n", "test.txt");
    EXPECT_EQ(commands.at(0).argument, "/tmp/out/a.json");
}

void expectError(const std::string& text, const std::string& fragment) {
    try {
        parseInputScript(text, "bad.txt");
        FAIL() << "no error for: " << text;
    } catch (const tstyles::InputError& error) {
        EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
    }
}

TEST(InputScript, MistakesNameFileAndLine) {
    expectError("wait 1\nfly away\n", "bad.txt:2: unknown command \"fly\"");
    expectError("drag left 1,2\n", "bad.txt:1: usage: drag BUTTON FROM TO [MOVES]");
    expectError("click thumb 1,2\n", "unknown mouse button \"thumb\"");
    expectError("key hyper+a\n", "unknown modifier \"hyper\"");
    expectError("key f13\n", "unknown key \"f13\"");
    expectError("move tstf:3\n", "expected two numbers");
    expectError("wait soon\n", "expected a number for wait");
    expectError("save-scene ${TSTYLES_SURELY_NOT_SET_ANYWHERE}/a.json\n", "TSTYLES_SURELY_NOT_SET_ANYWHERE is not set");
    expectError("open \"unterminated\n", "unterminated");
}

}  // namespace
