// Scene files: a full scene, the defaults, every kind of bad input, and save-then-load round trips.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/scene/scene_file.h"

namespace {

using tstyles::Scene;

// Parsing never touches the disk, so the origin can be any absolute path.
const std::filesystem::path origin = "/scenes/demo/bad_scene.json";

std::filesystem::path freshFolder(const std::string& name) {
    auto folder = std::filesystem::temp_directory_path() / ("tstyles_scene_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The message of the InputError that parsing `json` throws, or a failure when it throws none.
std::string parseError(const std::string& json) {
    try {
        tstyles::parseScene(json, origin);
    } catch (const tstyles::InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no InputError for " << json;
    return {};
}

const char* const fullScene = R"({
  "dataset": "../superellipsoid/series.json",
  "image": {"width": 640, "height": 480, "background": [0.1, 0.2, 0.3, 1.0]},
  "camera": {
    "orbit": {"target": [0.5, 0.4, 0.5], "distance": 3.0, "azimuth_deg": 30, "elevation_deg": 20},
    "fov_deg": 35,
    "projection": "orthographic"
  },
  "raycast": {"step": 0.01, "termination": 0.95},
  "stf": {
    "opacity": [{"at": 0.5, "opacity": 0.8}, {"at": 0.0, "opacity": 0.0}],
    "color": [{"at": 0.0, "color": [1.0, 0.9, 0.8]}]
  },
  "compositor": "temporal-max-change",
  "tstf": {
    "index": {"opacity": [{"at": 0, "opacity": 0.2}, {"at": 3, "opacity": 1.0}], "color": [{"at": 0, "color": [0.2, 0.4, 1.0]}]},
    "gradient": {"range": [0.1, 0.7], "opacity": [{"at": 0, "opacity": 1}], "color": [{"at": 0, "color": [0, 1, 0]}, {"at": 1, "color": [1, 0.5, 0]}]}
  },
  "final": "tstf"
})";

TEST(SceneFile, ReadsEveryKeyOfAFullScene) {
    const Scene scene = tstyles::parseScene(fullScene, origin);
    EXPECT_EQ(scene.dataset, std::filesystem::path("/scenes/superellipsoid/series.json"));
    EXPECT_EQ(scene.width, 640);
    EXPECT_EQ(scene.height, 480);
    EXPECT_EQ(scene.background, glm::dvec4(0.1, 0.2, 0.3, 1.0));
    const auto& orbit = std::get<tstyles::OrbitCamera>(scene.camera.pose);
    EXPECT_EQ(orbit.target, glm::dvec3(0.5, 0.4, 0.5));
    EXPECT_EQ(orbit.distance, 3.0);
    EXPECT_EQ(orbit.azimuthDeg, 30.0);
    EXPECT_EQ(orbit.elevationDeg, 20.0);
    EXPECT_EQ(scene.camera.fovDeg, 35.0);
    EXPECT_EQ(scene.camera.projection, tstyles::Projection::Orthographic);
    EXPECT_EQ(scene.raycast.step, 0.01);
    EXPECT_EQ(scene.raycast.termination, 0.95);
    // Nodes come back sorted by position.
    const std::vector<tstyles::OpacityNode> stfOpacity{{0.0, 0.0}, {0.5, 0.8}};
    EXPECT_EQ(scene.stf.curve.opacity, stfOpacity);
    EXPECT_EQ(scene.stf.curve.color.at(0).color, glm::dvec3(1.0, 0.9, 0.8));
    EXPECT_EQ(scene.compositor, tstyles::compositorNamed("temporal-max-change"));
    EXPECT_EQ(scene.indexTstf.curve.opacity.at(1).at, 3.0);
    EXPECT_EQ(scene.gradientTstf.rangeLow, 0.1);
    EXPECT_EQ(scene.gradientTstf.rangeHigh, 0.7);
    EXPECT_EQ(scene.gradientTstf.curve.color.size(), 2u);
    EXPECT_EQ(scene.finalMode, tstyles::FinalMode::Tstf);
}

TEST(SceneFile, AMinimalSceneTakesTheDefaults) {
    const Scene scene = tstyles::parseScene(R"({"dataset": "series.json"})", origin);
    Scene expected;
    expected.dataset = "/scenes/demo/series.json";
    EXPECT_EQ(scene, expected);
    EXPECT_EQ(scene.width, 512);
    EXPECT_EQ(scene.camera.fovDeg, 30.0);
    EXPECT_FALSE(scene.raycast.step.has_value());
    EXPECT_EQ(scene.compositor, tstyles::compositorNamed("temporal-mip"));
    EXPECT_EQ(scene.finalMode, tstyles::FinalMode::Modulate);
    EXPECT_EQ(scene.stf.curve.evaluate(0.25).opacity, 0.25);
}

TEST(SceneFile, APartialCurveKeepsTheDefaultOfTheOtherList) {
    const Scene scene = tstyles::parseScene(
        R"({"dataset": "s.json", "stf": {"color": [{"at": 0, "color": [1, 0, 0]}]}})", origin);
    EXPECT_EQ(scene.stf.curve.opacity, tstyles::defaultStf().curve.opacity);
    EXPECT_EQ(scene.stf.curve.evaluate(0.5).color, glm::dvec3(1.0, 0.0, 0.0));
}

TEST(SceneFile, ReadsALookAtCameraWithTheDefaultUp) {
    const Scene scene = tstyles::parseScene(
        R"({"dataset": "s.json", "camera": {"look_at": {"eye": [0, 0, 4], "target": [0, 0, 0]}}})", origin);
    const auto& lookAt = std::get<tstyles::LookAtCamera>(scene.camera.pose);
    EXPECT_EQ(lookAt.eye, glm::dvec3(0.0, 0.0, 4.0));
    EXPECT_EQ(lookAt.up, glm::dvec3(0.0, 1.0, 0.0));
}

TEST(SceneFile, ResolvesTheDatasetAgainstTheSceneFolder) {
    EXPECT_EQ(tstyles::parseScene(R"({"dataset": "./data/../series.json"})", origin).dataset,
              std::filesystem::path("/scenes/demo/series.json"));
    EXPECT_EQ(tstyles::parseScene(R"({"dataset": "/elsewhere/series.json"})", origin).dataset,
              std::filesystem::path("/elsewhere/series.json"));
}

TEST(SceneFile, AllowsComments) {
    const Scene scene =
        tstyles::parseScene("{\n  // which data\n  \"dataset\": \"s.json\" /* here */\n}", origin);
    EXPECT_EQ(scene.dataset, std::filesystem::path("/scenes/demo/s.json"));
}

TEST(SceneFile, TheDocumentedExampleParses) {
    const std::filesystem::path doc = std::filesystem::path(TSTYLES_SOURCE_DIR) / "docs" / "scene-format.md";
    const std::string text = readText(doc);
    const auto start = text.find("```json\n");
    ASSERT_NE(start, std::string::npos) << "no json block in " << doc;
    const auto end = text.find("```", start + 8);
    const Scene scene = tstyles::parseScene(text.substr(start + 8, end - start - 8), doc);
    EXPECT_EQ(scene.compositor, tstyles::compositorNamed("temporal-mip"));
    EXPECT_EQ(scene.dataset, (doc.parent_path() / "../superellipsoid/series.json").lexically_normal());
}

struct BadScene {
    const char* json;
    const char* keyPath;  // the JSON path the message must name
    const char* problem;  // a phrase of the problem the message must contain
};

// One line per kind of mistake; each message must name the file, the key and the problem.
const BadScene badScenes[] = {
    {R"({"dataset": "a.json",)", "", "line 1"},
    {R"({"dataset": "a.json", "x": 1e999})", "", "too large"},
    {R"([1, 2])", "", "expected an object at the top level, got an array"},
    {R"({"image": {"width": 64}})", "dataset", "missing"},
    {R"({"dataset": 3})", "dataset", "expected a string, got a number"},
    {R"({"dataset": ""})", "dataset", "empty"},
    {R"({"dataset": "a", "colour": [1, 0, 0]})", "colour", "unknown key"},
    {R"({"dataset": "a", "colour": [1, 0, 0]})", "colour", "dataset, image, camera"},
    {R"({"dataset": "a", "camera": {"orbit": {"azimuth": 3}}})", "camera.orbit.azimuth", "unknown key"},
    {R"({"dataset": "a", "camera": {"orbit": {"azimuth": 3}}})", "camera.orbit.azimuth", "azimuth_deg"},
    {R"({"dataset": "a", "image": {"width": "512"}})", "image.width", "expected a number, got a string"},
    {R"({"dataset": "a", "image": {"width": 0}})", "image.width", "must be in [1, 16384], got 0"},
    {R"({"dataset": "a", "image": {"height": 20000}})", "image.height", "must be in [1, 16384]"},
    {R"({"dataset": "a", "image": {"width": 512.5}})", "image.width", "expected an integer, got 512.5"},
    {R"({"dataset": "a", "image": {"background": [0, 0, 0]}})", "image.background", "4 numbers"},
    {R"({"dataset": "a", "image": {"background": [0, 0, 2, 1]}})", "image.background[2]",
     "must be in [0, 1], got 2"},
    {R"({"dataset": "a", "image": [512, 512]})", "image", "expected an object, got an array"},
    {R"({"dataset": "a", "camera": {"orbit": {"distance": 0}}})", "camera.orbit.distance",
     "must be > 0, got 0"},
    {R"({"dataset": "a", "camera": {"orbit": {"elevation_deg": 91}}})", "camera.orbit.elevation_deg",
     "must be in [-90, 90], got 91"},
    {R"({"dataset": "a", "camera": {"orbit": {"azimuth_deg": null}}})", "camera.orbit.azimuth_deg",
     "expected a number, got null"},
    {R"({"dataset": "a", "camera": {"orbit": {"target": [0, "1", 0]}}})", "camera.orbit.target[1]",
     "expected a number"},
    {R"({"dataset": "a", "camera": {"fov_deg": 180}})", "camera.fov_deg", "must be in (0, 180), got 180"},
    {R"({"dataset": "a", "camera": {"projection": "fisheye"}})", "camera.projection",
     "unknown value \"fisheye\"; allowed values: perspective, orthographic"},
    {R"({"dataset": "a", "camera": {"orbit": {}, "look_at": {"eye": [0, 0, 1], "target": [0, 0, 0]}}})",
     "camera", "exactly one"},
    {R"({"dataset": "a", "camera": {"look_at": {"target": [0, 0, 0]}}})", "camera.look_at.eye", "missing"},
    {R"({"dataset": "a", "camera": {"look_at": {"eye": [1, 1, 1], "target": [1, 1, 1]}}})",
     "camera.look_at.target", "must differ from eye"},
    {R"({"dataset": "a", "camera": {"look_at": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 0, 0]}}})",
     "camera.look_at.up", "zero"},
    {R"({"dataset": "a", "camera": {"look_at": {"eye": [0, 5, 0], "target": [0, 0, 0], "up": [0, 2, 0]}}})",
     "camera.look_at.up", "parallel"},
    {R"({"dataset": "a", "raycast": {"step": 0}})", "raycast.step", "must be > 0"},
    {R"({"dataset": "a", "raycast": {"termination": 0}})", "raycast.termination", "must be in (0, 1], got 0"},
    {R"({"dataset": "a", "raycast": {"termination": 1.01}})", "raycast.termination", "must be in (0, 1]"},
    {R"({"dataset": "a", "stf": {"opacity": {"at": 0}}})", "stf.opacity", "expected an array, got an object"},
    {R"({"dataset": "a", "stf": {"opacity": [{"at": 0, "opacity": 0}, {"at": 1, "opacity": 1}, {"at": 1.5, "opacity": 1}]}})",
     "stf.opacity[2].at", "must be in [0, 1], got 1.5"},
    {R"({"dataset": "a", "stf": {"opacity": [{"at": 0, "opacity": 1.5}]}})", "stf.opacity[0].opacity",
     "must be in [0, 1], got 1.5"},
    {R"({"dataset": "a", "stf": {"opacity": [{"at": 0}]}})", "stf.opacity[0].opacity", "missing"},
    {R"({"dataset": "a", "stf": {"opacity": [{"at": 0, "opacity": 1, "alpha": 1}]}})", "stf.opacity[0].alpha",
     "unknown key"},
    {R"({"dataset": "a", "stf": {"color": [{"at": 0, "color": [1, -0.5, 0]}]}})", "stf.color[0].color[1]",
     "must be in [0, 1], got -0.5"},
    {R"({"dataset": "a", "compositor": "temporal-median"})", "compositor",
     "allowed values: temporal-mip, temporal-average, temporal-max-change, temporal-min, temporal-std-dev, "
     "time-of-max, first-arrival, last-above, threshold-crossing, linear-trend, chronovolume, difference"},
    {R"({"dataset": "a", "final": "blend"})", "final", "allowed values: stf, tstf, modulate"},
    // Index TSTF nodes may lie before time-step 0 (a focus swept to the first step), but not as text.
    {R"({"dataset": "a", "tstf": {"index": {"opacity": [{"at": "1", "opacity": 1}]}}})",
     "tstf.index.opacity[0].at", "expected a number"},
    {R"({"dataset": "a", "tstf": {"gradient": {"range": [1, 0.5]}}})", "tstf.gradient.range",
     "low < high, got [1, 0.5]"},
    {R"({"dataset": "a", "tstf": {"gradient": {"range": [-0.5, -0.5]}}})", "tstf.gradient.range",
     "with low < high, got [-0.5, -0.5]"},
    {R"({"dataset": "a", "tstf": {"gradient": {"color": [{"at": 2, "color": [0, 0, 0]}]}}})",
     "tstf.gradient.color[0].at", "must be in [0, 1], got 2"},
    {R"({"dataset": "a", "tstf": {"max": {}}})", "tstf.max", "index, gradient"},
    {R"({"dataset": "a", "probes": [1, 2, 3]})", "probes[0]", "expected an array"},
    {R"({"dataset": "a", "probes": [[1, 2]]})", "probes[0]", "3 numbers"},
    {R"({"dataset": "a", "probes": {"at": [1, 2, 3]}})", "probes", "expected a list of places [x, y, z], got an object"},
    {R"({"dataset": "a", "probes": [[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0]]})",
     "probes", "at most 8 places, got 9"},
};

TEST(SceneFileErrors, NameTheFileTheKeyAndTheProblem) {
    for (const BadScene& bad : badScenes) {
        const std::string message = parseError(bad.json);
        EXPECT_NE(message.find(origin.string()), std::string::npos) << message;
        const std::string keyPart =
            bad.keyPath[0] ? std::string(": ") + bad.keyPath + ": " : std::string(": ");
        EXPECT_NE(message.find(keyPart), std::string::npos)
            << "expected key " << bad.keyPath << " in: " << message;
        EXPECT_NE(message.find(bad.problem), std::string::npos)
            << "expected \"" << bad.problem << "\" in: " << message;
    }
}

TEST(SceneFileErrors, NotJsonGivesTheLineAndColumn) {
    const std::string message = parseError("{\n  \"dataset\": \"a\",\n  \"image\": nope\n}");
    EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
    EXPECT_NE(message.find("line 3"), std::string::npos) << message;
    EXPECT_NE(message.find("column"), std::string::npos) << message;
}

TEST(SceneFileErrors, AMissingFileIsAnInputError) {
    const auto missing = freshFolder("missing") / "nowhere.json";
    try {
        tstyles::loadScene(missing);
        ADD_FAILURE() << "loading a missing file succeeded";
    } catch (const tstyles::InputError& error) {
        EXPECT_NE(std::string(error.what()).find("nowhere.json"), std::string::npos) << error.what();
    }
}

// A scene that departs from every default and uses every kind of value.
Scene everyFeatureScene(const std::filesystem::path& dataset) {
    Scene scene;
    scene.dataset = dataset;
    scene.camera.pose = tstyles::OrbitCamera{glm::dvec3(0.25, -1.5, 3.0), 4.125, -37.5, 12.3};
    scene.camera.fovDeg = 42.0;
    scene.camera.projection = tstyles::Projection::Orthographic;
    scene.width = 333;
    scene.height = 17;
    scene.background = {0.1, 0.2, 0.30000000000000004, 0.5};
    scene.raycast.step = 0.0123;
    scene.raycast.termination = 0.9;
    scene.stf.curve.opacity = {{0.0, 0.0}, {0.3, 0.2}, {0.3, 0.7}, {1.0, 1.0 / 3.0}};
    scene.stf.curve.color = {{0.1, {1.0, 0.0, 0.0}}, {0.9, {0.0, 0.5, 1.0}}};
    scene.compositor = tstyles::compositorNamed("temporal-average");
    scene.indexTstf.curve.opacity = {{0.0, 0.2}, {2.5, 1.0}, {7.0, 0.0}};
    scene.indexTstf.curve.color = {};
    scene.gradientTstf.rangeLow = 0.05;
    scene.gradientTstf.rangeHigh = 0.75;
    scene.gradientTstf.curve.opacity = {};
    scene.gradientTstf.curve.color = {{0.0, {0.0, 1.0, 0.0}}, {1.0, {1.0, 0.5, 0.0}}};
    scene.finalMode = tstyles::FinalMode::Stf;
    scene.probes = {{-95.5, 40.25, 500.0}, {0.1, 1e-7, -3.0}};
    return scene;
}

TEST(SceneFile, SaveThenLoadGivesBackTheSameScene) {
    const auto folder = freshFolder("round_trip");
    const auto dataset = (folder / "data" / "series.json").lexically_normal();
    const auto sceneFile = folder / "scenes" / "every_feature.json";
    std::filesystem::create_directories(sceneFile.parent_path());

    Scene orbit = everyFeatureScene(dataset);
    tstyles::saveScene(orbit, sceneFile);
    EXPECT_EQ(tstyles::loadScene(sceneFile), orbit);
    EXPECT_NE(readText(sceneFile).find("\"dataset\": \"../data/series.json\""), std::string::npos)
        << readText(sceneFile);

    Scene lookAt = everyFeatureScene(dataset);
    lookAt.camera.pose = tstyles::LookAtCamera{{1.0, 2.0, 3.0}, {0.5, 0.25, -1.0}, {0.0, 0.0, 1.0}};
    tstyles::saveScene(lookAt, sceneFile);
    EXPECT_EQ(tstyles::loadScene(sceneFile), lookAt);
}

TEST(SceneFile, SavingKeepsAutomaticValuesAutomatic) {
    const auto folder = freshFolder("automatic");
    Scene scene;
    scene.dataset = folder / "series.json";
    const auto sceneFile = folder / "scene.json";
    tstyles::saveScene(scene, sceneFile);
    const std::string text = readText(sceneFile);
    EXPECT_EQ(text.find("\"distance\""), std::string::npos) << text;
    EXPECT_EQ(text.find("\"target\""), std::string::npos) << text;
    EXPECT_EQ(text.find("\"step\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"termination\": 0.99"), std::string::npos) << text;
    EXPECT_NE(text.find("\"final\": \"modulate\""), std::string::npos) << text;
    EXPECT_EQ(tstyles::loadScene(sceneFile), scene);
}

TEST(SceneEnums, NamesReadBack) {
    for (const std::string& name : tstyles::temporalCompositorNames()) {
        const auto compositor = tstyles::temporalCompositorFromString(name);
        ASSERT_TRUE(compositor.has_value()) << name;
        EXPECT_EQ(tstyles::toString(*compositor), name);
    }
    for (const std::string& name : tstyles::finalModeNames()) {
        const auto mode = tstyles::finalModeFromString(name);
        ASSERT_TRUE(mode.has_value()) << name;
        EXPECT_EQ(tstyles::toString(*mode), name);
    }
    EXPECT_EQ(tstyles::toString(tstyles::compositorNamed("temporal-max-change")), "temporal-max-change");
    EXPECT_FALSE(tstyles::finalModeFromString("Modulate").has_value());
}

}  // namespace

namespace {

TEST(SceneFileNodes, GroupsAndStylesRoundTrip) {
    const std::string text = R"({
      "dataset": "d/series.json",
      "tstf": {"index": {
        "opacity": [{"at": 3, "opacity": 1.0, "group": 2}, {"at": 4, "opacity": 0.1}],
        "color": [{"at": 3, "style": "glossy-light-yellow", "group": 2}, {"at": 0, "color": [0, 0, 1]}]}}
    })";
    const auto folder = std::filesystem::temp_directory_path() / "tstyles_scene_groups";
    std::filesystem::create_directories(folder);
    const tstyles::Scene scene = tstyles::parseScene(text, folder / "s.json");
    const auto& curve = scene.indexTstf.curve;
    ASSERT_EQ(curve.opacity.size(), 2u);
    EXPECT_EQ(curve.opacity[0].group, 2);
    EXPECT_EQ(curve.opacity[1].group, 0);
    ASSERT_EQ(curve.color.size(), 2u);
    EXPECT_EQ(curve.color[1].style, "glossy-light-yellow");  // sorted: at 0 first
    EXPECT_EQ(curve.color[1].color, glm::dvec3(1.0));         // a style's tint defaults to white
    EXPECT_EQ(curve.color[1].group, 2);
    tstyles::saveScene(scene, folder / "s.json");
    EXPECT_EQ(tstyles::loadScene(folder / "s.json"), scene);
}

TEST(SceneFileNodes, BadGroupsAndStylesAreErrors) {
    auto expectError = [](const std::string& node, const std::string& fragment) {
        const std::string text = R"({"dataset": "d.json", "stf": {"color": [)" + node + "]}}";
        try {
            tstyles::parseScene(text, "bad.json");
            FAIL() << "expected an error for " << node;
        } catch (const tstyles::InputError& error) {
            EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
        }
    };
    expectError(R"({"at": 0, "color": [1, 1, 1], "group": 0})", "stf.color[0].group");
    expectError(R"({"at": 0, "color": [1, 1, 1], "group": 1.5})", "stf.color[0].group");
    expectError(R"({"at": 0, "style": ""})", "stf.color[0].style");
    expectError(R"({"at": 0})", "stf.color[0]");
}

}  // namespace

namespace {

TEST(SceneFileNodes, StyleFilesAreRelativeToTheSceneFolderAndWrittenBackRelative) {
    const auto folder = std::filesystem::temp_directory_path() / "tstyles_scene_style_paths";
    std::filesystem::create_directories(folder / "scenes");
    const std::string text = R"({"dataset": "d.json",
      "stf": {"color": [{"at": 0, "style": "../looks/sphere.png"}, {"at": 1, "style": "toon-orange"}]}})";
    const tstyles::Scene scene = tstyles::parseScene(text, folder / "scenes" / "s.json");
    EXPECT_EQ(scene.stf.curve.color[0].style, (folder / "looks" / "sphere.png").lexically_normal().string());
    EXPECT_EQ(scene.stf.curve.color[1].style, "toon-orange") << "built-in names stay names";
    const std::string saved = tstyles::sceneToJson(scene, folder / "scenes");
    EXPECT_NE(saved.find("\"../looks/sphere.png\""), std::string::npos) << saved;
    EXPECT_NE(saved.find("\"toon-orange\""), std::string::npos) << saved;
}

}  // namespace
