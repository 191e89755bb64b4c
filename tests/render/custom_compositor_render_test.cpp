// The scene's own compositor (CustomCompositor): code that reproduces a built-in compositor gives
// the built-in's image on a bundled scene, pixel for pixel, on every walk over the time-steps; a
// value for the gradient TSTF reads through its range like the built-ins'.
#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::testing {
namespace {

const std::filesystem::path kSourceDir = TSTYLES_SOURCE_DIR;

// Temporal MIP: the most opaque time-step, the earlier one on a tie. (The built-in breaks ties
// by the index TSTF's opacity too; the bundled scene's is the same for every time-step.)
constexpr const char* kMostOpaque = R"(float best = 0.0;
int winner = -1;
for (int i = 0; i < count; ++i) {
    if (hasData[i] && stf[i].a > best) {
        best = stf[i].a;
        winner = i;
    }
}
return float(winner);
)";

// Time of maximum: the densest time-step, the earlier one on a tie.
constexpr const char* kDensest = R"(int peak = -1;
for (int i = 0; i < count; ++i)
    if (hasData[i] && (peak < 0 || density[i] > density[peak])) peak = i;
return float(peak);
)";

CustomCompositor customCode(const char* glsl, CompositorReads reads) {
    CustomCompositor custom;
    custom.glsl = glsl;
    custom.origin = "custom_compositor_render_test.json";
    custom.reads = reads;
    return custom;
}

void expectIdentical(const Image& expected, const Image& actual, const std::string& what) {
    ASSERT_EQ(expected.width, actual.width);
    ASSERT_EQ(expected.height, actual.height);
    int different = 0;
    int visible = 0;
    for (int y = 0; y < expected.height; ++y)
        for (int x = 0; x < expected.width; ++x) {
            different += expected.at(x, y) != actual.at(x, y) ? 1 : 0;
            visible += expected.at(x, y).a > 0.0f ? 1 : 0;
        }
    EXPECT_EQ(different, 0) << what << ": pixels that differ";
    EXPECT_GT(visible, expected.width * expected.height / 20) << what << ": the image shows something";
}

// The bundled scene at 128 x 128 with `builtIn`, then with `custom`, under each walk.
void expectCustomEqualsBuiltIn(const std::string& sceneName, const std::string& dataset, TemporalCompositor builtIn,
                               const CustomCompositor& custom) {
    Scene scene = loadScene(kSourceDir / "data/scenes" / (sceneName + ".json"));
    scene.width = scene.height = 128;
    const Series& series = loadSeriesOnce(kSourceDir / "data" / dataset / "series.json");
    Scene own = scene;
    scene.compositor = builtIn;
    own.compositor = kCustomCompositor;
    own.compositorOptions.custom = custom;
    FrameOptions skipping;
    FrameOptions naive;
    naive.naive = true;
    renderSeries(series, scene);  // uploads the series once
    for (const auto& [walk, options] : {std::pair{"ray list", skipping}, std::pair{"naive", naive}})
        expectIdentical(drawWithCurrentSeries(scene, series.worldBounds(), options),
                        drawWithCurrentSeries(own, series.worldBounds(), options),
                        sceneName + " on " + dataset + ", " + walk);
}

TEST(CustomCompositorRender, ReproducingTemporalMipGivesTheBuiltInImage) {
    expectCustomEqualsBuiltIn("figure4-temporal-mip", "superellipsoid", compositorNamed("temporal-mip"),
                              customCode(kMostOpaque, CompositorReads::IndexTstf));
}

TEST(CustomCompositorRender, ReproducingTemporalMipGivesTheBuiltInImageOnPackedGroups) {
    expectCustomEqualsBuiltIn("figure4-temporal-mip", "superellipsoid-aligned",
                              compositorNamed("temporal-mip"),
                              customCode(kMostOpaque, CompositorReads::IndexTstf));
}

TEST(CustomCompositorRender, ReproducingTimeOfMaximumGivesTheBuiltInImage) {
    expectCustomEqualsBuiltIn("figure4-temporal-mip", "superellipsoid", compositorNamed("time-of-max"),
                              customCode(kDensest, CompositorReads::IndexTstf));
}

TEST(CustomCompositorRender, AValueForTheGradientTstfReadsThroughItsRange) {
    // The mean density of 0.2, 0.4 and 0.9 (0.5) on the range [0.25, 0.75]: the ramp's middle.
    const Series series = makeSeries({constantBox({0, 0, 0}, 0.2f), constantBox({0, 0, 0}, 0.4f),
                                      constantBox({0, 0, 0}, 0.9f)});
    const glm::dvec2 centre(0.35, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, 2.0, 64);
    scene.stf.curve = constantFunction({1, 1, 1}, 1.0);
    scene.gradientTstf.curve.opacity = {{0.0, 1.0}};
    scene.gradientTstf.curve.color = {{0.0, {0, 1, 0}}, {1.0, {1, 0.5, 0}}};
    scene.gradientTstf.rangeLow = 0.25;
    scene.gradientTstf.rangeHigh = 0.75;
    scene.finalMode = FinalMode::Tstf;
    scene.compositor = kCustomCompositor;
    scene.compositorOptions.custom = customCode(R"(float sum = 0.0;
int n = 0;
for (int i = 0; i < count; ++i) {
    if (!hasData[i]) continue;
    sum += density[i];
    n += 1;
}
return sum / float(n);
)",
                                                CompositorReads::GradientTstf);
    const Image image = renderSeries(series, scene);
    const glm::ivec2 pixel = pixelOf(centre, centre, 2.0, 64);
    const glm::vec4 expected(0.5f, 0.75f, 0.0f, 1.0f);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(image.at(pixel.x, pixel.y)[c], expected[c], 2e-3f) << "channel " << c;
}

}  // namespace
}  // namespace tstyles::testing
