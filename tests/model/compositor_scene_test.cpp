// The scene file's "compositor": names, objects with options, the scene's own code (inline or in a
// file) and its sandbox, what reads each compositor, and the automatic gradient range of each.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

const std::filesystem::path kOrigin = "/scenes/demo/compositor_scene.json";

std::filesystem::path freshFolder(const std::string& name) {
    const auto folder =
        std::filesystem::temp_directory_path() / ("tstyles_compositor_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

// A scene whose "compositor" is `compositor` (JSON text).
std::string sceneWith(const std::string& compositor) {
    return R"({"dataset": "series.json", "compositor": )" + compositor + "}";
}

// `code` as a JSON string.
std::string quotedCode(const std::string& code) { return nlohmann::json(code).dump(); }

std::string inlineCompositor(const std::string& code, const std::string& reads = "index-tstf") {
    return sceneWith(R"({"glsl": )" + quotedCode(code) + R"(, "reads": ")" + reads + "\"}");
}

std::string parseError(const std::string& json) {
    try {
        parseScene(json, kOrigin);
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no InputError for " << json;
    return {};
}

Scene roundTrip(const Scene& scene) {
    return parseScene(sceneToJson(scene, kOrigin.parent_path()), kOrigin);
}

TEST(CompositorScene, EveryNameReadsBackAndRoundTrips) {
    for (const std::string& name : temporalCompositorNames()) {
        const Scene scene = parseScene(sceneWith("\"" + name + "\""), kOrigin);
        EXPECT_EQ(scene.compositor, *temporalCompositorFromString(name)) << name;
        EXPECT_EQ(roundTrip(scene), scene) << name;
    }
}

TEST(CompositorScene, EveryCompositorButTheScenesOwnIsNamedForUsers) {
    const std::vector<std::string> names = temporalCompositorNames();
    EXPECT_EQ(names.size() + 1, temporalCompositors().size());
    for (const char* name : {"temporal-mip", "temporal-average", "temporal-max-change", "temporal-min",
                             "temporal-std-dev", "time-of-max", "first-arrival", "last-above", "linear-trend",
                             "chronovolume", "difference"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    EXPECT_EQ(std::find(names.begin(), names.end(), "custom"), names.end());
}

TEST(CompositorScene, ThresholdAndStepsAreReadAndWrittenBack) {
    const Scene arrival = parseScene(sceneWith(R"({"name": "first-arrival", "threshold": 0.4})"), kOrigin);
    EXPECT_EQ(arrival.compositor, compositorNamed("first-arrival"));
    EXPECT_EQ(arrival.compositorOptions.number(kThresholdOption), 0.4);
    EXPECT_EQ(roundTrip(arrival), arrival);
    EXPECT_NE(sceneToJson(arrival, kOrigin.parent_path()).find("\"threshold\": 0.4"), std::string::npos);

    const CompositorOption& steps = *compositorInfo(compositorNamed("difference")).options.find("steps");
    const Scene difference = parseScene(sceneWith(R"({"name": "difference", "steps": [3, 1]})"), kOrigin);
    EXPECT_EQ(difference.compositorOptions.timeSteps(steps), (TimeStepPair{3, 1}));
    EXPECT_EQ(difference.compositorOptions.timeStepsOn(steps, 5), glm::ivec2(3, 1));
    EXPECT_EQ(roundTrip(difference), difference);

    // Without steps: from the first time-step to the last, and written back without them.
    const Scene whole = parseScene(sceneWith(R"({"name": "difference"})"), kOrigin);
    EXPECT_EQ(whole.compositorOptions.timeStepsOn(steps, 7), glm::ivec2(0, 6));
    EXPECT_EQ(sceneToJson(whole, kOrigin.parent_path()).find("steps"), std::string::npos);
    // A name in an object without options is a name.
    EXPECT_EQ(parseScene(sceneWith(R"({"name": "temporal-min"})"), kOrigin).compositor,
              compositorNamed("temporal-min"));
}

TEST(CompositorScene, UnchangedPlacesAreReadAndWrittenBack) {
    // Fitted ("auto", the default of both keys) and neutral by default.
    const Scene fitted = parseScene(sceneWith(R"({"name": "temporal-mip", "unchanged": {}})"), kOrigin);
    ASSERT_TRUE(fitted.compositorOptions.unchanged);
    EXPECT_TRUE(fitted.compositorOptions.unchanged->automatic);
    EXPECT_EQ(fitted.compositorOptions.unchanged->opacity, 1.0);
    EXPECT_EQ(roundTrip(fitted), fitted);
    EXPECT_NE(sceneToJson(fitted, kOrigin.parent_path()).find("\"below\": \"auto\""), std::string::npos);

    const Scene given = parseScene(
        sceneWith(R"({"name": "time-of-max", "unchanged": {"below": 0.05, "tie": 0.01, "gain": 2.5, "boundary": 3.5,
                                                 "opacity": 0.25}})"),
        kOrigin);
    ASSERT_TRUE(given.compositorOptions.unchanged);
    EXPECT_FALSE(given.compositorOptions.unchanged->automatic);
    EXPECT_EQ(given.compositorOptions.unchanged->below, 0.05);
    EXPECT_EQ(given.compositorOptions.unchanged->tie, 0.01);
    EXPECT_EQ(given.compositorOptions.unchanged->gain, 2.5);
    EXPECT_EQ(given.compositorOptions.unchanged->boundary, 3.5);
    EXPECT_EQ(given.compositorOptions.unchanged->opacity, 0.25);
    EXPECT_EQ(roundTrip(given), given);

    // Every compositor that picks a time-step takes it; the others are named in the refusal.
    for (const std::string& name : temporalCompositorNames()) {
        const TemporalCompositorInfo& info = compositorInfo(*temporalCompositorFromString(name));
        const std::string json = sceneWith(R"({"name": ")" + name + R"(", "unchanged": {}})");
        if (info.takesUnchanged)
            EXPECT_EQ(roundTrip(parseScene(json, kOrigin)), parseScene(json, kOrigin)) << info.name;
        else
            EXPECT_NE(parseError(json).find("compositor.unchanged: " + std::string(info.name) + " does not pick"),
                      std::string::npos) << info.name;
    }
    // Without the key: time colours everywhere, as the paper's compositors show them.
    EXPECT_FALSE(parseScene(sceneWith(R"("temporal-mip")"), kOrigin).compositorOptions.unchanged);
}

TEST(CompositorScene, ASignedGradientRangeReadsAndRoundTrips) {
    const Scene scene = parseScene(
        R"({"dataset": "series.json", "compositor": "linear-trend", "tstf": {"gradient": {"range": [-0.2, 0.2]}}})",
        kOrigin);
    EXPECT_EQ(scene.gradientTstf.rangeLow, -0.2);
    EXPECT_EQ(scene.gradientTstf.rangeHigh, 0.2);
    EXPECT_EQ(roundTrip(scene), scene);
}

TEST(CompositorScene, DifferenceStepsBeyondTheSeriesNameTheField) {
    const Scene scene = parseScene(sceneWith(R"({"name": "difference", "steps": [0, 9]})"), kOrigin);
    try {
        scene.compositorOptions.timeStepsOn(*compositorInfo(scene.compositor).options.find("steps"), 4, kOrigin);
        FAIL() << "steps beyond the series";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("compositor.steps[1]"), std::string::npos) << message;
        EXPECT_NE(message.find("0 to 3"), std::string::npos) << message;
    }
}

TEST(CompositorScene, BadCompositorObjectsNameTheField) {
    const std::pair<std::string, std::string> cases[] = {
        {sceneWith(R"({"name": "temporal-mip", "threshold": 0.5})"), "compositor.threshold: temporal-mip takes no"},
        {sceneWith(R"({"name": "first-arrival", "threshold": 1.5})"), "compositor.threshold"},
        {sceneWith(R"({"name": "linear-trend", "steps": [0, 1]})"), "compositor.steps: linear-trend takes no steps"},
        {sceneWith(R"({"name": "difference", "steps": [0, 1.5]})"), "compositor.steps[1]: must be a whole"},
        {sceneWith(R"({"name": "difference", "steps": [0]})"), "compositor.steps"},
        {sceneWith(R"({"name": "no-such-one"})"), "compositor.name"},
        {sceneWith(R"({"threshold": 0.5})"), "compositor"},
        {sceneWith(R"({"name": "temporal-mip", "colour": 1})"), "compositor"},
        {sceneWith(R"({"name": "temporal-mip", "reads": "index-tstf"})"), "compositor.reads: only a compositor"},
        {sceneWith(R"({"name": "temporal-mip", "glsl": "return 0.0;", "reads": "index-tstf"})"),
         "compositor.name: a compositor with its own code has no name"},
        {sceneWith(R"({"glsl": "return 0.0;", "file": "a.glsl", "reads": "index-tstf"})"), "not both"},
        {sceneWith(R"({"glsl": "return 0.0;"})"), "compositor.reads: missing"},
        {sceneWith(R"({"glsl": "return 0.0;", "reads": "composited"})"), "compositor.reads"},
        {sceneWith(R"({"glsl": "  \n", "reads": "index-tstf"})"), "compositor.glsl: the compositor's code is empty"},
        {sceneWith(R"({"file": "nowhere.glsl", "reads": "index-tstf"})"), "compositor.file: no such file"},
        {sceneWith("42"), "compositor: expected a name or an object"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"below": 1.5}})"),
         "compositor.unchanged.below: must be in"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"below": "fit"}})"),
         "compositor.unchanged.below: expected \"auto\""},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"tie": 0.1}})"),
         "compositor.unchanged.tie: is fitted with \"below\": \"auto\""},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"below": 0.1, "tie": 2}})"), "compositor.unchanged.tie"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"gain": 2}})"), "compositor.unchanged.gain: is fitted"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"boundary": 2}})"),
         "compositor.unchanged.boundary: is fitted"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"below": 0.1, "boundary": -1}})"),
         "compositor.unchanged.boundary"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"below": 0.1, "gain": 0.5}})"),
         "compositor.unchanged.gain: must be in"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"opacity": -0.5}})"),
         "compositor.unchanged.opacity: must be in"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"shows": "grey"}})"), "compositor.unchanged"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": {"below": 0.1, "colour": 1}})"), "compositor.unchanged"},
        {sceneWith(R"({"name": "temporal-mip", "unchanged": true})"), "compositor.unchanged"},
    };
    for (const auto& [json, expected] : cases) {
        const std::string message = parseError(json);
        EXPECT_NE(message.find(kOrigin.string()), std::string::npos) << message;
        EXPECT_NE(message.find(expected), std::string::npos) << "expected \"" << expected << "\" in: " << message;
    }
}

TEST(CompositorScene, InlineCodeAndWhatReadsItRoundTrip) {
    const std::string code = "float best = -1.0;\nfor (int i = 0; i < count; ++i) best = max(best, density[i]);\n"
                             "return best;\n";
    const Scene scene = parseScene(inlineCompositor(code, "gradient-tstf"), kOrigin);
    EXPECT_EQ(scene.compositor, kCustomCompositor);
    ASSERT_TRUE(scene.compositorOptions.custom.has_value());
    EXPECT_EQ(scene.compositorOptions.custom->glsl, code);
    EXPECT_FALSE(scene.compositorOptions.custom->ownFile);
    EXPECT_EQ(compositorReads(scene), CompositorReads::GradientTstf);
    EXPECT_EQ(roundTrip(scene), scene);
}

TEST(CompositorScene, CodeInItsOwnFileStaysInThatFile) {
    const auto folder = freshFolder("file");
    std::filesystem::create_directories(folder / "compositors");
    const std::string code = "return 0.0;\n";
    std::ofstream(folder / "compositors/peak.glsl") << code;
    const auto sceneFile = folder / "scene.json";
    std::ofstream(sceneFile) << sceneWith(R"({"file": "compositors/peak.glsl", "reads": "index-tstf"})");
    const Scene scene = loadScene(sceneFile);
    ASSERT_TRUE(scene.compositorOptions.custom.has_value());
    EXPECT_EQ(scene.compositorOptions.custom->glsl, code);
    EXPECT_TRUE(scene.compositorOptions.custom->ownFile);
    EXPECT_EQ(compositorReads(scene), CompositorReads::IndexTstf);
    // Saved elsewhere, the scene names the same file, relative to its new folder.
    std::filesystem::create_directories(folder / "elsewhere");
    saveScene(scene, folder / "elsewhere/copy.json");
    std::ifstream saved(folder / "elsewhere/copy.json");
    const std::string text((std::istreambuf_iterator<char>(saved)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"file\": \"../compositors/peak.glsl\""), std::string::npos) << text;
    EXPECT_EQ(text.find("\"glsl\""), std::string::npos) << text;
    const Scene reloaded = loadScene(folder / "elsewhere/copy.json");
    EXPECT_EQ(reloaded.compositorOptions.custom, scene.compositorOptions.custom);
}

TEST(CompositorScene, WhatReadsEachCompositor) {
    EXPECT_EQ(compositorInfo(compositorNamed("temporal-mip")).reads, CompositorReads::IndexTstf);
    EXPECT_EQ(compositorInfo(compositorNamed("time-of-max")).reads, CompositorReads::IndexTstf);
    EXPECT_EQ(compositorInfo(compositorNamed("first-arrival")).reads, CompositorReads::IndexTstf);
    EXPECT_EQ(compositorInfo(compositorNamed("temporal-std-dev")).reads, CompositorReads::GradientTstf);
    EXPECT_EQ(compositorInfo(compositorNamed("linear-trend")).reads, CompositorReads::GradientTstf);
    EXPECT_EQ(compositorInfo(compositorNamed("difference")).reads, CompositorReads::GradientTstf);
    EXPECT_EQ(compositorInfo(compositorNamed("temporal-average")).reads, CompositorReads::Composited);
    EXPECT_EQ(compositorInfo(compositorNamed("chronovolume")).reads, CompositorReads::Composited);
    for (std::size_t line = 0; line < temporalCompositors().size(); ++line) {
        const TemporalCompositorInfo& info = temporalCompositors()[line];
        EXPECT_EQ(TemporalCompositor(line) == kCustomCompositor, std::string(info.shaderModule).empty()) << info.name;
    }
}

}  // namespace
}  // namespace tstyles
