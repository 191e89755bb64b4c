// Lit-sphere styles on a sphere of constant density: the colour comes from the style at the
// view-space normal, the style's alpha multiplies the opacity, and bad style files are errors.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/core/errors.h"
#include "tstyles/image/image_io.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 64;
constexpr double kViewHeight = 1.0;
constexpr double kRadius = 0.35;
const glm::dvec2 kCentre(0.5, 0.5);
// 8-bit style texels and mipmap filtering on top of the render tolerance.
constexpr float kTolerance = 6e-3f;

// A ball of density 1 with a two-voxel ramp to 0 at radius kRadius, centred in a unit box.
Series sphereSeries() {
    BoxSpec box;
    box.dims = glm::ivec3(33);
    box.spacing = glm::dvec3(1.0 / 32.0);
    box.density = [](glm::ivec3 voxel) {
        const double r = glm::length(glm::dvec3(voxel) / 32.0 - 0.5);
        return float(std::clamp((kRadius - r) / (2.0 / 32.0) + 0.5, 0.0, 1.0));
    };
    return makeSeries({box});
}

// An opaque surface at the sphere's radius, coloured by `style`.
Scene sphereScene(const std::string& style) {
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.45, 0.0}, {0.55, 1.0}};
    scene.stf.curve.color = {{0.0, {1.0, 1.0, 1.0}, style, 0}};
    scene.finalMode = FinalMode::Stf;
    return scene;
}

glm::vec4 pixelAt(const Image& image, glm::dvec2 world) {
    const glm::ivec2 pixel = pixelOf(world, kCentre, kViewHeight, kSize);
    return image.at(pixel.x, pixel.y);
}

void expectColor(glm::vec4 actual, glm::vec4 expected, const char* what) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(actual[c], expected[c], kTolerance) << what << " channel " << c;
}

TEST(StyleRender, AFlatColourStyleGivesThatColourEverywhere) {
    const auto style = writeStyle("flat", 16, 16, [](glm::vec2) { return glm::vec4(0.2f, 0.6f, 0.4f, 1.0f); });
    const Image image = renderSeries(sphereSeries(), sphereScene(style));
    for (glm::dvec2 offset : {glm::dvec2(0, 0), glm::dvec2(-0.2, 0.1), glm::dvec2(0.25, -0.2)})
        expectColor(pixelAt(image, kCentre + offset), {0.2f, 0.6f, 0.4f, 1.0f}, "flat style");
    expectColor(pixelAt(image, {0.05, 0.05}), glm::vec4(0.0f), "outside the sphere");
}

TEST(StyleRender, ATwoColourSplitStyleColoursTheLeftAndRightHalves) {
    const auto style = writeStyle("split", 64, 64, [](glm::vec2 normal) {
        return normal.x < 0.0f ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 1, 0, 1);
    });
    const Image image = renderSeries(sphereSeries(), sphereScene(style));
    // Away from the middle, where the normal's x is clearly negative or positive.
    expectColor(pixelAt(image, kCentre + glm::dvec2(-0.22, 0.0)), {1, 0, 0, 1}, "left half");
    expectColor(pixelAt(image, kCentre + glm::dvec2(-0.15, 0.15)), {1, 0, 0, 1}, "upper left");
    expectColor(pixelAt(image, kCentre + glm::dvec2(0.22, 0.0)), {0, 1, 0, 1}, "right half");
    expectColor(pixelAt(image, kCentre + glm::dvec2(0.15, -0.15)), {0, 1, 0, 1}, "lower right");
}

TEST(StyleRender, UpInTheStyleImageIsUpOnTheScreen) {
    const auto style = writeStyle("top-bottom", 64, 64, [](glm::vec2 normal) {
        return normal.y > 0.0f ? glm::vec4(0, 0, 1, 1) : glm::vec4(1, 1, 0, 1);
    });
    const Image image = renderSeries(sphereSeries(), sphereScene(style));
    expectColor(pixelAt(image, kCentre + glm::dvec2(0.0, 0.22)), {0, 0, 1, 1}, "upper half");
    expectColor(pixelAt(image, kCentre + glm::dvec2(0.0, -0.22)), {1, 1, 0, 1}, "lower half");
}

TEST(StyleRender, AContourStyleLeavesTheCentreTransparentAndTheRimOpaque) {
    const auto style = writeStyle("contour", 64, 64, [](glm::vec2 normal) {
        const float r = glm::length(normal);
        const float alpha = std::clamp((r - 0.5f) / 0.3f, 0.0f, 1.0f);
        return glm::vec4(1.0f, 1.0f, 1.0f, alpha);
    });
    const Image image = renderSeries(sphereSeries(), sphereScene(style));
    EXPECT_LT(pixelAt(image, kCentre).a, 0.02f) << "the centre faces the viewer: transparent";
    EXPECT_LT(pixelAt(image, kCentre + glm::dvec2(0.1, 0.05)).a, 0.05f);
    // Near the silhouette the normal lies in the image plane: the rim is opaque and white.
    const glm::vec4 rim = pixelAt(image, kCentre + glm::dvec2(0.97 * kRadius, 0.0));
    EXPECT_GT(rim.a, 0.9f);
    EXPECT_NEAR(rim.r / rim.a, 1.0f, kTolerance);
}

TEST(StyleRender, WhereTheGradientVanishesTheSphereCentreColourIsUsed) {
    // Constant density has no gradient: every sample reads the style's centre, never NaN.
    const auto style = writeStyle("centre", 64, 64, [](glm::vec2 normal) {
        return glm::length(normal) < 0.3f ? glm::vec4(0, 0, 1, 1) : glm::vec4(1, 0, 0, 1);
    });
    const Series series = makeSeries({constantBox({0.15, 0.15, 0.0}, 1.0f)});
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 1.0}};
    scene.stf.curve.color = {{0.0, {1.0, 1.0, 1.0}, style, 0}};
    scene.finalMode = FinalMode::Stf;
    const Image image = renderSeries(series, scene);
    expectColor(pixelAt(image, kCentre), {0, 0, 1, 1}, "centre colour");
    for (float value : image.rgba) ASSERT_FALSE(std::isnan(value));
}

TEST(StyleRender, BetweenTwoStyleNodesTheColourBlendsTheirLookups) {
    const auto red = writeStyle("red", 8, 8, [](glm::vec2) { return glm::vec4(1, 0, 0, 1); });
    const auto blue = writeStyle("blue", 8, 8, [](glm::vec2) { return glm::vec4(0, 0, 1, 1); });
    // Constant density 0.25 sits a quarter of the way from the red node (0) to the blue one (1).
    const Series series = makeSeries({constantBox({0.15, 0.15, 0.0}, 0.25f)});
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 1.0}};
    scene.stf.curve.color = {{0.0, {1, 1, 1}, red, 0}, {1.0, {1, 1, 1}, blue, 0}};
    scene.finalMode = FinalMode::Stf;
    const Image image = renderSeries(series, scene);
    expectColor(pixelAt(image, kCentre), {0.75f, 0.0f, 0.25f, 1.0f}, "blend of two styles");
}

TEST(StyleRender, IndexTstfStylesColourEachTimeStep) {
    const auto split = writeStyle("index-split", 64, 64, [](glm::vec2 normal) {
        return normal.x < 0.0f ? glm::vec4(1, 0, 1, 1) : glm::vec4(0, 1, 1, 1);
    });
    Scene scene = sphereScene("");
    scene.stf.curve.color = {{0.0, {1, 1, 1}}};
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 1, 1}, split, 0}};
    scene.finalMode = FinalMode::Tstf;
    const Image image = renderSeries(sphereSeries(), scene);
    expectColor(pixelAt(image, kCentre + glm::dvec2(-0.22, 0.0)), {1, 0, 1, 1}, "left");
    expectColor(pixelAt(image, kCentre + glm::dvec2(0.22, 0.0)), {0, 1, 1, 1}, "right");
}

void expectStyleError(const std::string& style, const std::string& fragment) {
    try {
        renderSeries(sphereSeries(), sphereScene(style));
        FAIL() << "expected an InputError for " << style;
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
    }
}

TEST(StyleRender, BadStyleFilesAreErrorsNamingTheFileAndTheProblem) {
    const auto missing = (styleImageFolder() / "missing.png").string();
    expectStyleError(missing, "missing.png");
    expectStyleError(missing, "no such file");
    const auto wide = writeStyle("wide", 32, 16, [](glm::vec2) { return glm::vec4(1); });
    expectStyleError(wide, "must be square");
    expectStyleError(wide, "32x16");
    const auto garbage = styleImageFolder() / "garbage.png";
    std::ofstream(garbage) << "this is not an image";
    expectStyleError(garbage.string(), "garbage.png");
    expectStyleError("no-such-built-in-style", "no built-in style");
}

}  // namespace
}  // namespace tstyles::testing
