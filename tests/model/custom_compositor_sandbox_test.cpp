// The sandbox of a scene's own compositor, checked when the scene is read: its inputs, its own
// variables and GLSL's built-in math, loops bounded by the time-step count; anything else is an
// InputError naming the line of the compositor's code.
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles {
namespace {

const std::filesystem::path kOrigin = "/scenes/demo/sandbox.json";

std::string sceneWithCode(const std::string& code) {
    return R"({"dataset": "series.json", "compositor": {"glsl": )" + nlohmann::json(code).dump() +
           R"(, "reads": "index-tstf"}})";
}

// The problem the sandbox finds in `code`, or "" when it accepts it.
std::string sandboxProblem(const std::string& code) {
    try {
        parseScene(sceneWithCode(code), kOrigin);
    } catch (const InputError& error) {
        return error.what();
    }
    return {};
}

TEST(CustomCompositorSandbox, AcceptsCodeOverItsInputs) {
    const char* accepted[] = {
        // time of peak
        "int peak = -1;\nfor (int i = 0; i < count; ++i)\n    if (hasData[i] && (peak < 0 || density[i] > density[peak])) "
        "peak = i;\nreturn float(peak);",
        // every input, swizzles, built-in math, nested loops, a declaration list, break and continue
        "float spread = 0.0, weight = 0.0;\nfor (int i = 0; i < count; i++) {\n  if (!hasData[i] || !inMask[i]) "
        "continue;\n  for (int j = i + 1; j < count; ++j) {\n    spread = max(spread, abs(density[j] - density[i]) "
        "/ max(time[j] - time[i], 1e-6));\n  }\n  weight += stf[i].a * length(stf[i].rgb);\n  if (weight > 10.0) "
        "break;\n}\nreturn spread * clamp(weight, 0.0, 1.0);",
        // arrays of its own, sized by the capacity; comments may say anything
        "float values[MAX_TIME_STEPS]; // while texture #define\n/* for (;;) timeSteps */\nfor (int k = 0; k < "
        "count; ++k) values[k] = density[k];\nreturn values[0] == values[0] ? 1.0 : 0.0;",
        // the loop variable compared, not changed
        "int n = 0;\nfor (int i = 0; i < count; ++i) { if (i == 2 || i <= 1 || i != 0) n += i; }\nreturn float(n);",
    };
    for (const char* code : accepted) EXPECT_EQ(sandboxProblem(code), "") << code;
}

TEST(CustomCompositorSandbox, RejectsWhatLeavesTheSandboxNamingTheLine) {
    const std::pair<const char*, const char*> rejected[] = {
        {"float a = 0.0;\nfloat b = texture(volume, vec3(0.0)).r;\nreturn b;", "line 2: \"texture\" is not available"},
        {"float t = 0.0;\n\nt = timeSteps.steps[0].time.x;\nreturn t;", "line 3: \"timeSteps\" is not available"},
        {"return gl_FragCoord.x;", "line 1: \"gl_FragCoord\" is not available"},
        {"int i = 0;\nwhile (i < count) i++;\nreturn 0.0;", "line 2: \"while\" is not allowed"},
        {"int i = 0;\ndo { i++; } while (i < count);\nreturn 0.0;", "line 2: \"do\" is not allowed"},
        {"float s = 0.0;\nfor (int i = 0; i < 100; ++i) s += 1.0;\nreturn s;", "line 2: a loop must read"},
        {"float s = 0.0;\nfor (int i = 0; i <= count; ++i) s += 1.0;\nreturn s;", "line 2: a loop must read"},
        {"float s = 0.0;\nfor (int i = 0; i < count; i += 2) s += 1.0;\nreturn s;", "line 2: a loop must read"},
        {"for (int i = 0; i < count; ++i) {\n  i = 0;\n}\nreturn 0.0;", "line 2: the loop variable \"i\""},
        {"for (int i = 0; i < count; ++i) {\n\n  i--;\n}\nreturn 0.0;", "line 3: the loop variable \"i\""},
        {"for (int i = 0; i < count; ++i) {\n  i %= 2;\n}\nreturn 0.0;", "line 2: the loop variable \"i\""},
        {"for (int i = 0; i < count; ++i) {\n  i <<= 1;\n}\nreturn 0.0;", "line 2: the loop variable \"i\""},
        {"for (int i = 0; i < count; ++i) {\n  --i;\n}\nreturn 0.0;", "line 2: the loop variable \"i\""},
        {"return 0.0;\n#define X 1", "line 2: preprocessor directives are not allowed"},
        {"return 0.0;\n}\nfloat leak() {\n  return 1.0;", "line 2: a \"}\" without its \"{\""},
        {"if (count > 0) {\n  return 1.0;\n", "line 2: a \"{\" without its \"}\""},
        {"uniform float u;\nreturn u;", "line 1: \"uniform\" is not allowed"},
        {"return 0.0; discard;", "line 1: \"discard\" is not allowed"},
    };
    for (const auto& [code, expected] : rejected) {
        const std::string problem = sandboxProblem(code);
        EXPECT_NE(problem.find(kOrigin.string() + ": compositor.glsl: " + expected), std::string::npos)
            << "expected \"" << expected << "\" for\n" << code << "\ngot: " << problem;
    }
}

}  // namespace
}  // namespace tstyles
