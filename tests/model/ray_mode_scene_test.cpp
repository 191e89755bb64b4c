// The scene file's "ray": names and objects with options, their defaults, round trips, and the
// refusals (an unknown mode, another mode's option, a list too long or of the wrong length, a
// value out of range, a mode that means nothing with the scene's compositor).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/scene/animation.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/scene_keys.h"

namespace tstyles {
namespace {

const std::filesystem::path kOrigin = "/scenes/demo/ray_scene.json";

std::string sceneWith(const std::string& ray, const std::string& compositor = "\"temporal-mip\"") {
    return R"({"dataset": "series.json", "compositor": )" + compositor + R"(, "ray": )" + ray + "}";
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

Scene roundTrip(const Scene& scene) { return parseScene(sceneToJson(scene, kOrigin.parent_path()), kOrigin); }

TEST(RayModeScene, EveryModeReadsByNameAndRoundTrips) {
    for (const std::string& name : rayModeNames()) {
        const Scene scene = parseScene(sceneWith("\"" + name + "\""), kOrigin);
        EXPECT_EQ(scene.rayMode, *rayModeFromString(name)) << name;
        EXPECT_EQ(roundTrip(scene), scene) << name;
        const Scene asObject = parseScene(sceneWith(R"({"mode": ")" + name + "\"}"), kOrigin);
        EXPECT_EQ(asObject, scene) << name;
    }
}

TEST(RayModeScene, CompositeIsTheDefaultAndLeavesTheFileAsItWas) {
    const Scene scene = parseScene(R"({"dataset": "series.json"})", kOrigin);
    EXPECT_EQ(scene.rayMode, kCompositeRay);
    EXPECT_EQ(sceneToJson(scene, kOrigin.parent_path()).find("\"ray\""), std::string::npos);
}

TEST(RayModeScene, OptionsTakeTheirDefaultsAndRoundTrip) {
    const Scene iso = parseScene(sceneWith(R"({"mode": "isosurface"})"), kOrigin);
    const RayModeInfo& info = rayModeInfo(iso.rayMode);
    EXPECT_EQ(iso.rayOptions.numbers(*info.options.find("values")), std::vector<double>{0.5});
    EXPECT_EQ(iso.rayOptions.numbers(*info.options.find("opacities")), std::vector<double>{1.0});

    const Scene two = parseScene(sceneWith(R"({"mode": "isosurface", "values": [0.3, 0.7]})"), kOrigin);
    EXPECT_EQ(two.rayOptions.numbers(*info.options.find("opacities")), (std::vector<double>{1.0, 1.0}))
        << "one opacity per value by default";
    const Scene given =
        parseScene(sceneWith(R"({"mode": "isosurface", "values": [0.3, 0.7], "opacities": [0.25, 1]})"), kOrigin);
    EXPECT_EQ(given.rayOptions.numbers(*info.options.find("opacities")), (std::vector<double>{0.25, 1.0}));
    EXPECT_EQ(roundTrip(given), given);

    const Scene attenuated = parseScene(sceneWith(R"({"mode": "attenuated-maximum", "attenuation": 2.5})"), kOrigin);
    EXPECT_EQ(attenuated.rayOptions.number(*rayModeInfo(attenuated.rayMode).options.find("attenuation")), 2.5);
    EXPECT_EQ(roundTrip(attenuated), attenuated);
}

TEST(RayModeScene, BadRaysAreRefusedNamingTheKey) {
    EXPECT_NE(parseError(sceneWith("\"mip\"")).find("ray"), std::string::npos);
    EXPECT_NE(parseError(sceneWith("\"mip\"")).find("maximum"), std::string::npos) << "the names are listed";
    EXPECT_NE(parseError(sceneWith("3")).find("expected a name or an object"), std::string::npos);
    EXPECT_NE(parseError(sceneWith(R"({"mode": "maximum", "values": [0.5]})")).find("maximum takes no values"),
              std::string::npos);
    EXPECT_NE(parseError(sceneWith(R"({"mode": "maximum", "colour": 1})")).find("colour"), std::string::npos);
    EXPECT_NE(parseError(sceneWith(R"({"mode": "isosurface", "values": [0.1, 0.2, 0.3, 0.4, 0.5]})"))
                  .find("expected 1 to 4 numbers, got 5"),
              std::string::npos);
    EXPECT_NE(parseError(sceneWith(R"({"mode": "isosurface", "values": []})")).find("expected 1 to 4 numbers"),
              std::string::npos);
    EXPECT_NE(parseError(sceneWith(R"({"mode": "isosurface", "values": [0.3, 0.6], "opacities": [1]})"))
                  .find("ray.opacities: has 1 entries, one for each of the 2 values"),
              std::string::npos);
    EXPECT_NE(parseError(sceneWith(R"({"mode": "isosurface", "opacities": [1.5]})")).find("ray.opacities"),
              std::string::npos);
    EXPECT_NE(parseError(sceneWith(R"({"mode": "attenuated-maximum", "attenuation": -1})")).find("ray.attenuation"),
              std::string::npos);
}

TEST(RayModeScene, PairsThatMeanNothingAreRefusedWithAReason) {
    // temporal-average composites the time-steps' colours: there is no value to take the maximum of.
    for (const char* mode : {"maximum", "minimum", "attenuated-maximum", "isosurface"}) {
        const std::string error = parseError(sceneWith("\"" + std::string(mode) + "\"", "\"temporal-average\""));
        EXPECT_NE(error.find("ray.mode: " + std::string(mode) + " compares a value along the ray"), std::string::npos)
            << error;
    }
    for (const char* mode : {"composite", "average", "additive"})
        EXPECT_NO_THROW(parseScene(sceneWith("\"" + std::string(mode) + "\"", "\"temporal-average\""), kOrigin));
    // A compositor that picks a time-step shows densities in [0, 1]: a negative iso-value is never met.
    EXPECT_NE(parseError(sceneWith(R"({"mode": "isosurface", "values": [0.5, -0.2]})")).find("ray.values[1]"),
              std::string::npos);
    // One that reads the gradient TSTF gives signed values (a trend): a negative one is met.
    EXPECT_NO_THROW(parseScene(sceneWith(R"({"mode": "isosurface", "values": [-0.2]})", "\"linear-trend\""), kOrigin));
}

TEST(RayModeScene, TheKeyTableHasTheModesAndTheirOptions) {
    for (const char* path : {"ray", "ray.mode", "ray.attenuation", "ray.values", "ray.opacities"})
        EXPECT_NE(findSceneKey(path), nullptr) << path;
    // The attenuation animates directly; it is no number of a scene in another mode.
    const SceneKey* attenuation = findSceneKey("ray.attenuation");
    ASSERT_TRUE(attenuation && attenuation->numeric);
    Scene scene = parseScene(sceneWith(R"({"mode": "attenuated-maximum"})"), kOrigin);
    EXPECT_EQ(attenuation->numeric->get(scene), std::optional<double>(1.0));
    EXPECT_TRUE(attenuation->numeric->set(scene, 3.0));
    EXPECT_EQ(attenuation->numeric->get(scene), std::optional<double>(3.0));
    scene.rayMode = rayModeNamed("maximum");
    EXPECT_EQ(attenuation->numeric->get(scene), std::nullopt);
}

TEST(RayModeScene, AnIsoValueAnimatesThroughItsKeyPath) {
    const std::string text = R"({"dataset": "series.json", "ray": {"mode": "isosurface", "values": [0.2]},
        "animation": {"frames": 11, "tracks": [{"value": "ray.values[0]", "keys": [[0, 0.2], [10, 0.7]]}]}})";
    const Scene scene = parseScene(text, kOrigin);
    const Scene middle = sceneAtFrame(scene, 5);
    const RayModeOption& values = *rayModeInfo(middle.rayMode).options.find("values");
    ASSERT_EQ(middle.rayOptions.numbers(values).size(), 1u);
    EXPECT_NEAR(middle.rayOptions.numbers(values)[0], 0.45, 1e-12);
    // A key outside the option's range fails on reading, naming the key.
    const std::string beyond = R"({"dataset": "series.json", "ray": {"mode": "isosurface"},
        "animation": {"frames": 2, "tracks": [{"value": "ray.values[0]", "keys": [[0, 0.2], [1, 1.5]]}]}})";
    EXPECT_NE(parseError(beyond).find("ray.values[0]"), std::string::npos);
}

}  // namespace
}  // namespace tstyles
