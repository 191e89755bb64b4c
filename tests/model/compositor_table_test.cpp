// The table of temporal compositors: each line's module and options are what the reader, the key
// table and the shaders take, so that a compositor is a module and a line, and nothing else.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/scene_keys.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

const std::filesystem::path kOrigin = "/scenes/table.json";

std::string shaderText(const std::string& module) {
    std::ifstream in(std::filesystem::path(TSTYLES_SOURCE_DIR) / "shaders" / module);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const char* glslTypeOf(CompositorOptionKind kind) {
    switch (kind) {
        case CompositorOptionKind::Number: return "float";
        case CompositorOptionKind::TimeStepPair: return "ivec2";
        case CompositorOptionKind::Choice: return "int";
    }
    return "";
}

Scene sceneWith(const std::string& compositor) {
    return parseScene(R"({"dataset": "/data/series.json", "compositor": )" + compositor + "}", kOrigin);
}

std::string parseError(const std::string& compositor) {
    try {
        sceneWith(compositor);
    } catch (const InputError& error) {
        return error.what();
    }
    return {};
}

TEST(CompositorTable, EveryModuleDeclaresTheUniformOfEachOptionItTakes) {
    for (const TemporalCompositorInfo& info : temporalCompositors()) {
        if (std::string(info.shaderModule).empty()) continue;  // the scene's own code
        const std::string text = shaderText(info.shaderModule);
        ASSERT_FALSE(text.empty()) << info.shaderModule;
        for (const CompositorOption& option : info.options) {
            const std::string declaration =
                "\nuniform " + std::string(glslTypeOf(option.kind)) + " " + option.uniform + ";";
            EXPECT_NE(text.find(declaration), std::string::npos) << info.name << " does not declare " << option.uniform;
        }
    }
}

TEST(CompositorTable, OptionsOfOneKeyAreOneOption) {
    for (const TemporalCompositorInfo& info : temporalCompositors()) {
        for (const CompositorOption& option : info.options) {
            const auto all = compositorOptionsOfAll();
            const auto first = std::find_if(all.begin(), all.end(), [&](const CompositorOption* known) {
                return std::string(known->key) == option.key;
            });
            ASSERT_NE(first, all.end());
            const CompositorOption& shared = **first;
            EXPECT_EQ(std::string(shared.uniform), option.uniform) << option.key;
            EXPECT_EQ(shared.kind, option.kind) << option.key;
            EXPECT_EQ(shared.defaultNumber, option.defaultNumber) << option.key;
            EXPECT_EQ(shared.range.describe(), option.range.describe()) << option.key;
            EXPECT_EQ(shared.choiceNames(), option.choiceNames()) << option.key;
        }
    }
}

TEST(CompositorTable, EveryOptionIsASceneKeyAndANumberTakesItsRange) {
    for (const CompositorOption* option : compositorOptionsOfAll()) {
        const std::string path = std::string("compositor.") + option->key;
        const SceneKey* key = findSceneKey(path);
        ASSERT_NE(key, nullptr) << path;
        EXPECT_NE(key->allowed.find(option->help), std::string::npos) << path;
        for (const std::string& name : compositorsTaking(option->key))
            EXPECT_NE(key->allowed.find("`" + name + "`"), std::string::npos) << path << " names " << name;
        ASSERT_EQ(key->numeric.has_value(), option->kind == CompositorOptionKind::Number) << path;
        if (key->numeric) {
            EXPECT_EQ(key->numeric->range.describe(), option->range.describe()) << path;
        }
    }
}

// The compositor added as one module and one line: the reader, the writer and the key table take
// its options with nothing else changed.
TEST(CompositorTable, TheThresholdCrossingIsReadWrittenAndAnimatedFromItsLine) {
    const Scene falling = sceneWith(R"({"name": "threshold-crossing", "threshold": 0.3, "direction": "falling"})");
    const TemporalCompositorInfo& info = compositorInfo(falling.compositor);
    EXPECT_EQ(std::string(info.name), "threshold-crossing");
    const CompositorOption& direction = *info.options.find("direction");
    EXPECT_EQ(falling.compositorOptions.choice(direction), 1u);
    EXPECT_EQ(falling.compositorOptions.number(kThresholdOption), 0.3);
    const std::string written = sceneToJson(falling, kOrigin.parent_path());
    EXPECT_NE(written.find(R"("direction": "falling")"), std::string::npos) << written;
    EXPECT_EQ(parseScene(written, kOrigin), falling);

    // The defaults: rising, 0.5, and both written so that the file says them.
    const Scene plain = sceneWith(R"({"name": "threshold-crossing"})");
    EXPECT_EQ(plain.compositorOptions.choice(direction), 0u);
    EXPECT_NE(sceneToJson(plain, kOrigin.parent_path()).find(R"("direction": "rising")"), std::string::npos);
    EXPECT_NE(sceneToJson(plain, kOrigin.parent_path()).find(R"("threshold": 0.5)"), std::string::npos);

    EXPECT_NE(parseError(R"({"name": "threshold-crossing", "direction": "sideways"})")
                  .find("compositor.direction: unknown value \"sideways\"; allowed values: rising, falling"),
              std::string::npos)
        << parseError(R"({"name": "threshold-crossing", "direction": "sideways"})");
    EXPECT_NE(parseError(R"({"name": "first-arrival", "direction": "rising"})")
                  .find("compositor.direction: first-arrival takes no direction"),
              std::string::npos);
    EXPECT_NE(parseError(R"({"name": "threshold-crossing", "threshold": 1.5})")
                  .find("compositor.threshold: must be in [0, 1], got 1.5"),
              std::string::npos);

    // Its threshold is a numeric key that an animation track moves.
    Scene moved = falling;
    ASSERT_TRUE(numericSceneKey("compositor.threshold")->set(moved, 0.7));
    EXPECT_EQ(moved.compositorOptions.number(kThresholdOption), 0.7);
    EXPECT_EQ(numericSceneKey("compositor.threshold")->get(moved), 0.7);
    Scene mip = moved;
    mip.compositor = compositorNamed("temporal-mip");
    EXPECT_FALSE(numericSceneKey("compositor.threshold")->get(mip).has_value());
    EXPECT_FALSE(numericSceneKey("compositor.threshold")->set(mip, 0.2));
}

}  // namespace
}  // namespace tstyles
