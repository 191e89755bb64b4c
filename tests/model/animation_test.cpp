// Animation sequences: interpolation in closed form, the scene at a frame, the presets, the
// animation and annotations sections read, written and refused.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/scene/animation_presets.h"
#include "tstyles/scene/keyframe_recording.h"
#include "tstyles/scene/scene_file.h"

namespace {

using namespace tstyles;

// Parsing never touches the disk, so the origin can be any absolute path.
const std::filesystem::path origin = "/scenes/demo/animated.json";

// A scene with a focus group (nodes at 0.5 and 1.5, group 1) on the index TSTF.
std::string sceneWith(const std::string& animation) {
    return R"({
  "dataset": "../data/series.json",
  "camera": {"orbit": {"azimuth_deg": 30, "elevation_deg": 20}},
  "compositor": "temporal-mip",
  "tstf": {"index": {
    "opacity": [{"at": 0, "opacity": 0.1}, {"at": 0.5, "opacity": 1, "group": 1}, {"at": 1.5, "opacity": 1, "group": 1}],
    "color": [{"at": 0, "color": [0.2, 0.2, 0.2]}, {"at": 1, "color": [1, 0, 0], "group": 1}]}}
  )" + (animation.empty() ? std::string() : ", \"animation\": " + animation) +
           "}";
}

std::string parseError(const std::string& text) {
    try {
        parseScene(text, origin);
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no InputError for " << text;
    return {};
}

// The InputError for `text` says `expected`.
void expectError(const std::string& text, const std::string& expected) {
    const std::string message = parseError(text);
    EXPECT_NE(message.find(expected), std::string::npos) << "expected \"" << expected << "\" in: " << message;
}

double azimuthOf(const Scene& scene) { return std::get<OrbitCamera>(scene.camera.pose).azimuthDeg; }

TEST(AnimationTrack, InterpolatesLinearlySmoothlyOrHoldsAndClampsOutsideItsKeys) {
    AnimationTrack track{ValueTrackTarget{"camera.orbit.azimuth_deg"}, {{10, 0}, {20, 100}, {30, 50}}};
    EXPECT_DOUBLE_EQ(track.valueAt(0), 0.0);
    EXPECT_DOUBLE_EQ(track.valueAt(15), 50.0);
    EXPECT_DOUBLE_EQ(track.valueAt(25), 75.0);
    EXPECT_DOUBLE_EQ(track.valueAt(40), 50.0);
    track.interpolation = Interpolation::Smooth;
    // smoothstep(0.25) = 0.25^2 * (3 - 0.5) = 0.15625
    EXPECT_DOUBLE_EQ(track.valueAt(12.5), 15.625);
    EXPECT_DOUBLE_EQ(track.valueAt(15), 50.0);
    track.interpolation = Interpolation::Constant;
    EXPECT_DOUBLE_EQ(track.valueAt(19.9), 0.0);
    EXPECT_DOUBLE_EQ(track.valueAt(20), 100.0);
}

TEST(SceneAtFrame, MovesTheFocusGroupAndAnyNumberOfTheScene) {
    const Scene scene = parseScene(sceneWith(R"({"frames": 9, "tracks": [
        {"focus": "tstf.index", "group": 1, "keys": [[0, 1], [8, 7]]},
        {"value": "camera.orbit.azimuth_deg", "keys": [[0, 30], [8, 70]]},
        {"value": "exposure.last", "keys": [[0, 0], [8, 4]]}]})"),
                                   origin);
    ASSERT_EQ(scene.animation.frames, 9);
    const Scene frame3 = sceneAtFrame(scene, 3);
    EXPECT_TRUE(frame3.animation.empty());
    // The group's centre (1.0 at frame 0) moves to 1 + 6 * 3/8 = 3.25; its nodes keep their spacing.
    EXPECT_DOUBLE_EQ(*groupCentre(frame3.indexTstf.curve, 1), 3.25);
    EXPECT_DOUBLE_EQ(frame3.indexTstf.curve.opacity[1].at, 2.75);
    EXPECT_DOUBLE_EQ(frame3.indexTstf.curve.opacity[2].at, 3.75);
    EXPECT_DOUBLE_EQ(frame3.indexTstf.curve.opacity[0].at, 0.0);  // not in the group: stays
    EXPECT_DOUBLE_EQ(azimuthOf(frame3), 45.0);
    // exposure.last is a whole time-step: 4 * 3/8 = 1.5 rounds to 2.
    EXPECT_EQ(frame3.exposure.last, 2);
    EXPECT_EQ(frame3.dataset, scene.dataset);
}

TEST(SceneAtFrame, KeepsAGradientRangeFittedToTheData) {
    Scene scene = parseScene(sceneWith(R"({"tracks": [{"value": "camera.orbit.azimuth_deg", "keys": [[0, 0], [4, 90]]}]})"),
                             origin);
    scene.gradientTstf.automaticRange = true;
    scene.gradientTstf.rangeLow = 0.0;
    scene.gradientTstf.rangeHigh = 0.37;
    const Scene frame = sceneAtFrame(scene, 2);
    EXPECT_TRUE(frame.gradientTstf.automaticRange);
    EXPECT_DOUBLE_EQ(frame.gradientTstf.rangeHigh, 0.37);
    EXPECT_EQ(scene.animation.frames, 5);  // no "frames": the movie ends on the last key
}

TEST(AnimationSection, SavesAndLoadsBackEqual) {
    Scene scene = parseScene(sceneWith(R"({"frames": 30, "fps": 12, "tracks": [
        {"focus": "tstf.index", "group": 1, "interpolation": "constant", "keys": [[0, 0], [10, 1], [20, 2]]},
        {"value": "stf.opacity[1].at", "interpolation": "smooth", "keys": [[0, 0.2], [29, 0.8]]}]})"),
                             origin);
    scene.annotations.legend = true;
    scene.annotations.legendCorner = Corner::BottomLeft;
    scene.annotations.title = "Isabel, 2003";
    scene.annotations.box = true;
    scene.exposure = Exposure{1, 3};
    const auto folder = std::filesystem::temp_directory_path() / "tstyles_animation_round_trip";
    std::filesystem::create_directories(folder);
    saveScene(scene, folder / "scene.json");
    Scene loaded = loadScene(folder / "scene.json");
    loaded.dataset = scene.dataset;  // the saved path is relative to the new folder
    EXPECT_EQ(loaded, scene);
}

TEST(AnimationSection, RefusesBadTracksNamingTheKey) {
    expectError(sceneWith(R"({"tracks": [{"value": "camera.orbit.azimuth_deg", "keys": [[0, 1]], "speed": 2}]})"),
                "animation.tracks[0].speed: unknown key");
    expectError(sceneWith(R"({"tracks": [{"value": "camera.orbit.azimuth_deg", "keys": [[5, 1], [2, 3]]}]})"),
                "animation.tracks[0].keys[1][0]: frames must increase from key to key: 2 comes after 5");
    expectError(sceneWith(R"({"tracks": [{"focus": "tstf.index", "group": 4, "keys": [[0, 1]]}]})"),
                "animation.tracks[0].group: the curve tstf.index has no node in group 4");
    expectError(sceneWith(R"({"tracks": [{"value": "camera.orbit.elevation_deg", "keys": [[0, 10], [9, 95]]}]})"),
                "animation.tracks[0].keys[1]: value 95 does not fit the scene: camera.orbit.elevation_deg: must "
                        "be in [-90, 90], got 95");
    expectError(sceneWith(R"({"tracks": [{"value": "stf.opacity[7].at", "keys": [[0, 0.5]]}]})"),
                "animation.tracks[0].value: the scene has no number at \"stf.opacity[7].at\"");
    expectError(sceneWith(R"({"tracks": [{"value": "camera.orbit.spin", "keys": [[0, 0.5]]}]})"),
                "animation.tracks[0].keys[0]: value 0.5 does not fit the scene: camera.orbit.spin: unknown key");
    expectError(sceneWith(R"({"tracks": []})"),
                "animation.tracks: needs at least one track");
    expectError(sceneWith(R"({"tracks": [{"value": "image.width", "keys": [[0, 64]], "interpolation": "cubic"}]})"),
                "animation.tracks[0].interpolation: unknown value \"cubic\"; allowed values: linear, smooth, constant");
    expectError(R"({"dataset": "d.json", "annotations": {"legend": {"corner": "middle"}}})",
                "annotations.legend.corner: unknown value \"middle\"");
    expectError(R"({"dataset": "d.json", "exposure": {"first": 4, "last": 2}})",
                "exposure.last: is 2, before exposure.first (4)");
}

TEST(Exposure, FitsTheSeriesOrNamesTheKey) {
    EXPECT_EQ(Exposure{}.stepsOf(8), glm::ivec2(0, 7));
    EXPECT_EQ((Exposure{2, 5}.stepsOf(8)), glm::ivec2(2, 5));
    try {
        (void)Exposure{0, 9}.stepsOf(8, "scene.json");
        FAIL() << "no error for exposure.last past the series";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "scene.json: exposure.last: is 9 (the series has 8 time-steps, 0 to 7)");
    }
}

TEST(AnimationPresets, FocusSweepHoldsEachTimeStepForAnEqualShare) {
    const Scene scene = parseScene(sceneWith(""), origin);
    const AnimationTrack sweep = focusSweep(scene, CurveName::IndexTstf, 1, 4, 16, true, "--sweep-focus");
    for (int frame = 0; frame < 16; ++frame) EXPECT_DOUBLE_EQ(sweep.valueAt(frame), double(frame / 4)) << frame;
    const AnimationTrack smooth = focusSweep(scene, CurveName::IndexTstf, 1, 4, 16, false, "--sweep-focus");
    EXPECT_DOUBLE_EQ(smooth.valueAt(0), 0.0);
    EXPECT_DOUBLE_EQ(smooth.valueAt(15), 3.0);
    EXPECT_THROW(focusSweep(scene, CurveName::IndexTstf, 2, 4, 16, true, "--sweep-focus"), InputError);
}

TEST(AnimationPresets, ExposureGrowsSlidesOrPlaysBack) {
    Scene scene = parseScene(sceneWith(""), origin);
    scene.animation.frames = 12;
    scene.animation.tracks = exposureBuildUp(4, 12);
    EXPECT_EQ(sceneAtFrame(scene, 0).exposure.stepsOf(4), glm::ivec2(0, 0));
    EXPECT_EQ(sceneAtFrame(scene, 5).exposure.stepsOf(4), glm::ivec2(0, 1));
    EXPECT_EQ(sceneAtFrame(scene, 11).exposure.stepsOf(4), glm::ivec2(0, 3));
    scene.animation.tracks = exposureWindow(5, 2, 12);  // windows 0-1, 1-2, 2-3, 3-4: three frames each
    EXPECT_EQ(sceneAtFrame(scene, 0).exposure.stepsOf(5), glm::ivec2(0, 1));
    EXPECT_EQ(sceneAtFrame(scene, 7).exposure.stepsOf(5), glm::ivec2(2, 3));
    EXPECT_EQ(sceneAtFrame(scene, 11).exposure.stepsOf(5), glm::ivec2(3, 4));
    scene.animation.tracks = playback(4, 12);
    EXPECT_EQ(sceneAtFrame(scene, 4).exposure.stepsOf(4), glm::ivec2(1, 1));
    scene.animation.tracks = {orbitTurn(scene, 360.0, 12, "--orbit")};
    EXPECT_DOUBLE_EQ(azimuthOf(sceneAtFrame(scene, 3)), 30.0 + 90.0);
}

}  // namespace

namespace {

TEST(RecordedKeys, BecomeTracksOfTheNumbersThatMove) {
    using namespace tstyles;
    Scene first = parseScene(sceneWith(""), origin);
    Scene second = first;
    std::get<OrbitCamera>(second.camera.pose).azimuthDeg = 120.0;
    second.indexTstf.curve.opacity[1].at = 1.2;  // a node moved (staying before the next one)
    const Animation animation = animationFromRecordedKeys({{20, second}, {0, first}}, 12);
    EXPECT_EQ(animation.frames, 21);
    EXPECT_EQ(animation.framesPerSecond, 12);
    ASSERT_EQ(animation.tracks.size(), 2u);
    Scene animated = first;
    animated.animation = animation;
    const Scene middle = sceneAtFrame(animated, 10);
    EXPECT_DOUBLE_EQ(azimuthOf(middle), 75.0);
    EXPECT_DOUBLE_EQ(middle.indexTstf.curve.opacity[1].at, 0.85);
    EXPECT_EQ(sceneAtFrame(animated, 20), [&] {
        Scene last = second;
        last.animation = {};
        return last;
    }());

    Scene grown = first;
    grown.stf.curve.opacity.push_back({0.9, 0.5});
    EXPECT_THROW(animationFromRecordedKeys({{0, first}, {10, grown}}, 24), InputError);
}

}  // namespace

namespace {

TEST(AnimationPresets, CameraRisesAndMovesInEasedBetweenTheEnds) {
    using namespace tstyles;
    Scene scene = parseScene(sceneWith(""), origin);  // orbit at azimuth 30, elevation 20
    scene.animation.frames = 11;
    scene.animation.tracks = {elevationChange(scene, 90.0, 11, "--elevation"), zoomBy(scene, 4.0, 2.0, 11, "--zoom")};
    const Scene first = sceneAtFrame(scene, 0);
    const Scene middle = sceneAtFrame(scene, 5);
    const Scene last = sceneAtFrame(scene, 10);
    EXPECT_DOUBLE_EQ(std::get<OrbitCamera>(first.camera.pose).elevationDeg, 20.0);
    EXPECT_DOUBLE_EQ(*std::get<OrbitCamera>(first.camera.pose).distance, 4.0);
    // Halfway through a smooth ease is halfway in value.
    EXPECT_DOUBLE_EQ(std::get<OrbitCamera>(middle.camera.pose).elevationDeg, 54.5);
    EXPECT_DOUBLE_EQ(*std::get<OrbitCamera>(middle.camera.pose).distance, 3.0);
    EXPECT_DOUBLE_EQ(std::get<OrbitCamera>(last.camera.pose).elevationDeg, 89.0);  // stops short of the pole
    EXPECT_DOUBLE_EQ(*std::get<OrbitCamera>(last.camera.pose).distance, 2.0);
    scene.camera.pose = LookAtCamera{};
    EXPECT_THROW(zoomBy(scene, 4.0, 2.0, 11, "--zoom"), InputError);
}

}  // namespace
