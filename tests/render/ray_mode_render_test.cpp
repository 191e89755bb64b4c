// The ray modes (ray_modes.h) rendered and compared with closed-form expectations: the maximum
// and minimum projections keep one sample in its time colour, the largest change the sample that
// changes most, the average of a constant is the
// constant, additive sums opacity over the length, an iso-surface lies where the value crosses and
// is lit by its normal.
#include <cmath>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/core/errors.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 64;
constexpr double kViewHeight = 2.0;
// As analytic_render_test: 16-bit densities, 1024-entry transfer tables, float arithmetic.
constexpr float kTolerance = 2e-3f;

void expectPixel(const Image& image, glm::ivec2 pixel, glm::vec4 expected, const std::string& what) {
    const glm::vec4 actual = image.at(pixel.x, pixel.y);
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(actual[c], expected[c], kTolerance)
            << what << " at pixel (" << pixel.x << ", " << pixel.y << ") channel " << c;
}

// Two time-steps on one 8x8x8 box: time-step 0 has density 0.3 everywhere, time-step 1 has 0.2
// except a bright cube of 0.9 at its centre (samples 3 and 4 on each axis, world 0.3 to 0.4).
// temporal-mip picks time-step 0 (red) around the cube and time-step 1 (green) inside it.
Series dimSlabAndBrightCube() {
    BoxSpec dim = constantBox({0.0, 0.0, 0.0}, 0.3f);
    BoxSpec cube = constantBox({0.0, 0.0, 0.0}, 0.2f);
    cube.density = [](glm::ivec3 sample) {
        const bool inside = glm::all(glm::greaterThanEqual(sample, glm::ivec3(3))) &&
                            glm::all(glm::lessThanEqual(sample, glm::ivec3(4)));
        return inside ? 0.9f : 0.2f;
    };
    return makeSeries({dim, cube});
}

const glm::dvec2 kBoxCentre(0.35, 0.35);

Scene redGreenScene() {
    Scene scene = orthographicSceneLookingDownZ(kBoxCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 0.0}, {1.0, 1.0}};  // opacity = density
    scene.stf.curve.color = {{0.0, {1.0, 1.0, 1.0}}};
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}};
    scene.finalMode = FinalMode::Modulate;
    scene.compositor = compositorNamed("temporal-mip");
    return scene;
}

glm::ivec2 boxPixel(glm::dvec2 world) { return pixelOf(world, kBoxCentre, kViewHeight, kSize); }

TEST(RayModeRender, MaximumShowsTheBrightestPlaceInItsTimeStepsColourWhereCompositingHidesIt) {
    const Series series = dimSlabAndBrightCube();
    Scene scene = redGreenScene();
    scene.rayMode = rayModeNamed("maximum");
    const Image maximum = renderSeries(series, scene);
    // The pixel shows the one sample as opaque as the STF makes it (no correction for length).
    expectPixel(maximum, boxPixel(kBoxCentre), {0.0f, 0.9f, 0.0f, 0.9f}, "the bright cube, time-step 1");
    expectPixel(maximum, boxPixel({0.05, 0.05}), {0.3f, 0.0f, 0.0f, 0.3f}, "the dim slab, time-step 0");
    expectPixel(maximum, boxPixel({-0.4, 0.35}), glm::vec4(0.0f), "beside the box");

    scene.rayMode = kCompositeRay;
    const glm::vec4 composite = renderSeries(series, scene).at(boxPixel(kBoxCentre).x, boxPixel(kBoxCentre).y);
    // The slab in front (0.3 of 0.7 at 0.3 per 0.1) leaves about 0.34 of the light: the cube is there
    // but the slab's red dominates.
    EXPECT_GT(composite.r, composite.g) << "compositing shows the slab in front of the cube";

    scene.rayMode = rayModeNamed("minimum");
    expectPixel(renderSeries(series, scene), boxPixel(kBoxCentre), {0.3f, 0.0f, 0.0f, 0.3f},
                "the minimum along the ray through the cube: the slab's 0.3");
}

TEST(RayModeRender, AttenuatedMaximumWithoutAttenuationIsThePlainMaximum) {
    const Series series = dimSlabAndBrightCube();
    Scene scene = redGreenScene();
    scene.rayMode = rayModeNamed("maximum");
    const Image maximum = renderSeries(series, scene);
    scene.rayMode = rayModeNamed("attenuated-maximum");
    scene.rayOptions.values["attenuation"] = 0.0;
    EXPECT_EQ(renderSeries(series, scene).rgba, maximum.rgba);

    // Attenuated by the slab in front (opacity 0.3 per 0.1 over the 0.3 before the cube and part of
    // the cube itself), 0.9 sinks below the 0.3 met first: the ray shows the slab.
    scene.rayOptions.values["attenuation"] = 1.0;
    const glm::vec4 attenuated = renderSeries(series, scene).at(boxPixel(kBoxCentre).x, boxPixel(kBoxCentre).y);
    EXPECT_NEAR(attenuated.r, 0.3f, kTolerance);
    EXPECT_NEAR(attenuated.g, 0.0f, kTolerance);
}

TEST(RayModeRender, MaximumWithTimeOfMaxColoursTheTimeStepOfThePeak) {
    // Three time-steps; a place peaks in time-step 2 (0.8), another in time-step 0 (0.6); the rest
    // is 0.1 throughout. Each peak is two samples wide on every axis, so that it is flat between
    // them (world 0.4 to 0.5 and 0.1 to 0.2 across the view, where the pixels looked at lie). The
    // maximum along the ray through each shows the time-step of its peak.
    auto peakAt = [](int low, float peak) {
        BoxSpec box = constantBox({0.0, 0.0, 0.0}, 0.1f);
        box.density = [low, peak](glm::ivec3 sample) {
            const bool inside = glm::all(glm::greaterThanEqual(sample, glm::ivec3(low, low, 2))) &&
                                glm::all(glm::lessThanEqual(sample, glm::ivec3(low + 1, low + 1, 3)));
            return inside ? peak : 0.1f;
        };
        return box;
    };
    const Series series = makeSeries({peakAt(1, 0.6f), constantBox({0.0, 0.0, 0.0}, 0.1f), peakAt(4, 0.8f)});
    Scene scene = orthographicSceneLookingDownZ(kBoxCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 0.0}, {1.0, 1.0}};
    scene.stf.curve.color = {{0.0, {1.0, 1.0, 1.0}}};
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}, {2.0, {0, 0, 1}}};
    scene.finalMode = FinalMode::Modulate;
    scene.compositor = compositorNamed("time-of-max");
    scene.rayMode = rayModeNamed("maximum");
    const Image image = renderSeries(series, scene);
    expectPixel(image, boxPixel({0.45, 0.45}), {0.0f, 0.0f, 0.8f, 0.8f}, "the peak of time-step 2");
    expectPixel(image, boxPixel({0.15, 0.15}), {0.6f, 0.0f, 0.0f, 0.6f}, "the peak of time-step 0");
    expectPixel(image, boxPixel({0.65, 0.05}), {0.1f, 0.0f, 0.0f, 0.1f}, "no peak: all tie, the first time-step");
}

// Three time-steps of 0.5 everywhere but two layers across the view (z samples 2-3 and 5-6; each
// is flat between its two samples). The bright layer is 0.95 in time-step 0 and 0.85 after: it
// changes by 0.1. The changing layer is 0.5, 0.5, then 0.9: it changes by 0.4, in time-step 2.
// Which of them lies in front does not matter to the largest change.
Series brightLayerAndChangingLayer() {
    auto layers = [](float bright, float changing) {
        BoxSpec box = constantBox({0.0, 0.0, 0.0}, 0.5f);
        box.density = [bright, changing](glm::ivec3 sample) {
            if (sample.z == 2 || sample.z == 3) return changing;
            if (sample.z == 5 || sample.z == 6) return bright;
            return 0.5f;
        };
        return box;
    };
    return makeSeries({layers(0.95f, 0.5f), layers(0.85f, 0.5f), layers(0.85f, 0.9f)});
}

Scene redGreenBlueScene() {
    Scene scene = redGreenScene();
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}, {2.0, {0, 0, 1}}};
    return scene;
}

TEST(RayModeRender, LargestChangeShowsTheTimeOfTheLayerThatChangesMost) {
    const Series series = brightLayerAndChangingLayer();
    Scene scene = redGreenBlueScene();
    scene.rayMode = rayModeNamed("largest-change");
    // The changing layer's peak, time-step 2 (blue), as opaque as the STF makes 0.9; the scene asks
    // for no unchanged places, so the compositor measures the change for the mode alone.
    ASSERT_FALSE(scene.compositorOptions.unchanged);
    expectPixel(renderSeries(series, scene), boxPixel(kBoxCentre), {0.0f, 0.0f, 0.9f, 0.9f},
                "the layer that changes by 0.4, at its peak");
    // The maximum shows the brighter layer instead, in its time-step 0 (red).
    scene.rayMode = rayModeNamed("maximum");
    expectPixel(renderSeries(series, scene), boxPixel(kBoxCentre), {0.95f, 0.0f, 0.0f, 0.95f},
                "the brightest sample: the layer that changes by 0.1");

    // With unchanged places up to a change of 0.2 the bright layer has no time; the changing layer
    // still makes the pixel. Where nothing changes more than 0.2 (a scene whose changing layer
    // stays 0.5), the pixel is the grey of the sample that changes most, at the unchanged share.
    scene.rayMode = rayModeNamed("largest-change");
    UnchangedTime unchanged;
    unchanged.automatic = false;
    unchanged.below = 0.2;
    unchanged.opacity = 0.5;
    scene.compositorOptions.unchanged = unchanged;
    expectPixel(renderSeries(series, scene), boxPixel(kBoxCentre), {0.0f, 0.0f, 0.9f, 0.9f},
                "the changing layer, unchanged places around it");
    auto still = [](float bright) {
        BoxSpec box = constantBox({0.0, 0.0, 0.0}, 0.5f);
        box.density = [bright](glm::ivec3 sample) { return sample.z == 5 || sample.z == 6 ? bright : 0.5f; };
        return box;
    };
    const Series quiet = makeSeries({still(0.95f), still(0.85f), still(0.85f)});
    // The bright layer's grey: the STF's white at 0.5 of its opacity, 0.95 (time-step 0 ranks first).
    expectPixel(renderSeries(quiet, scene), boxPixel(kBoxCentre), {0.475f, 0.475f, 0.475f, 0.475f},
                "no time colour: the grey of the place that changes most");
}

// With the max density change the compositor's value is the change itself: the largest change
// along the ray is the maximum of that value, pixel for pixel.
TEST(RayModeRender, LargestChangeOfTheMaxDensityChangeIsItsMaximum) {
    const Series series = brightLayerAndChangingLayer();
    Scene scene = redGreenBlueScene();
    scene.compositor = compositorNamed("temporal-max-change");
    scene.gradientTstf.rangeLow = 0.0;
    scene.gradientTstf.rangeHigh = 0.4;
    scene.rayMode = rayModeNamed("maximum");
    const Image maximum = renderSeries(series, scene);
    scene.rayMode = rayModeNamed("largest-change");
    const Image largest = renderSeries(series, scene);
    EXPECT_EQ(largest.rgba, maximum.rgba);
    EXPECT_GT(maximum.at(boxPixel(kBoxCentre).x, boxPixel(kBoxCentre).y).a, 0.0f) << "the picture is not empty";
}

TEST(RayModeRender, LargestChangeIsRefusedWithACompositorThatCompositesTheTimeSteps) {
    try {
        parseScene(R"({"dataset": "x/series.json", "compositor": "temporal-average", "ray": "largest-change"})",
                   "scene.json");
        FAIL() << "temporal-average with the largest change was read";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("ray.mode"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("temporal-average"), std::string::npos) << error.what();
    }
}

TEST(RayModeRender, AverageOfAConstantIsTheConstantHoweverThick) {
    const Series series = makeSeries({constantBox({0.0, 0.0, 0.0}, 0.5f)});
    Scene scene = orthographicSceneLookingDownZ(kBoxCentre, kViewHeight, kSize);
    const glm::dvec3 colour(0.2, 0.6, 1.0);
    scene.stf.curve = constantFunction(colour, 0.4);
    scene.finalMode = FinalMode::Stf;
    scene.compositor = compositorNamed("temporal-average");
    scene.rayMode = rayModeNamed("average");
    for (double step : {0.05, 0.013}) {
        scene.raycast.step = step;
        const Image image = renderSeries(series, scene);
        expectPixel(image, boxPixel(kBoxCentre), glm::vec4(glm::vec3(colour * 0.4), 0.4f),
                    "the constant, step " + std::to_string(step));
    }
}

TEST(RayModeRender, AdditiveSumsOpacityOverTheLengthWithoutAbsorption) {
    const Series series = makeSeries({constantBox({0.0, 0.0, 0.0}, 0.5f)});
    Scene scene = orthographicSceneLookingDownZ(kBoxCentre, kViewHeight, kSize);
    const glm::dvec3 colour(1.0, 0.5, 0.25);
    scene.stf.curve = constantFunction(colour, 0.05);
    scene.finalMode = FinalMode::Stf;
    scene.rayMode = rayModeNamed("additive");
    // 0.05 per reference length (0.1) over the box's 0.7: 0.35, where compositing gives 1 - 0.95^7.
    const double sum = 0.05 * kConstantBoxWidth / kConstantBoxSpacing;
    const Image image = renderSeries(series, scene);
    expectPixel(image, boxPixel(kBoxCentre), glm::vec4(glm::vec3(colour * sum), float(sum)), "the sum");
    // Thick enough and each channel saturates at 1: 0.5 x 7 = 3.5 of opacity, of blue 0.25 x 3.5.
    scene.stf.curve = constantFunction(colour, 0.5);
    expectPixel(renderSeries(series, scene), boxPixel(kBoxCentre), {1.0f, 1.0f, 0.875f, 1.0f}, "saturated");
}

// A cone of density around (0.5, 0.5, 0.5) in a box [0, 1]^3 of 33^3 samples: 1 at the centre,
// falling linearly to 0 at radius 0.4. Its 0.5 iso-surface is the sphere of radius 0.2.
Series densityCone() {
    BoxSpec box;
    box.dims = glm::ivec3(33);
    box.spacing = glm::dvec3(1.0 / 32.0);
    box.density = [](glm::ivec3 sample) {
        const double r = glm::length(glm::dvec3(sample) / 32.0 - glm::dvec3(0.5));
        return float(std::clamp(1.0 - r / 0.4, 0.0, 1.0));
    };
    return makeSeries({box});
}

TEST(RayModeRender, IsosurfaceIsTheSphereWhereTheValueCrossesLitByItsNormal) {
    const Series series = densityCone();
    // Pixels 0.01 wide centred on the sphere: their centres lie at 0.5 +- 0.005 + k 0.01.
    const glm::dvec2 centre(0.5, 0.5);
    const double viewHeight = 1.28;
    const int size = 128;
    Scene scene = orthographicSceneLookingDownZ(centre, viewHeight, size);
    const glm::dvec3 colour(1.0, 0.8, 0.4);
    scene.stf.curve = constantFunction(colour, 0.02);  // the surface's opacity is its own
    scene.finalMode = FinalMode::Stf;
    scene.rayMode = rayModeNamed("isosurface");
    scene.rayOptions.values["values"] = std::vector<double>{0.5};
    const Image image = renderSeries(series, scene);
    // A pixel at offset d from the axis meets the sphere where its normal's z is sqrt(1 - (d/0.2)^2):
    // headlight 0.25 + 0.75 n_z. The normal is the sampled density's gradient (central
    // differences of a cone sampled 1/32 apart): measured 1e-5 off at the axis, 0.006 at d = 0.165,
    // where the light changes fastest with the normal.
    for (int column : {64, 70, 76, 80}) {
        const double x = centre.x + ((column + 0.5) / size - 0.5) * viewHeight;
        const double y = centre.y + (0.5 - (64 + 0.5) / size) * viewHeight;
        const double d = glm::length(glm::dvec2(x, y) - centre);
        const double nz = std::sqrt(1.0 - (d / 0.2) * (d / 0.2));
        const double light = 0.25 + 0.75 * nz;
        const glm::vec4 actual = image.at(column, 64);
        EXPECT_NEAR(actual.a, 1.0f, kTolerance) << "covered at d = " << d;
        EXPECT_NEAR(actual.r, light * colour.r, 0.01) << "lit by the normal at d = " << d;
        EXPECT_NEAR(actual.b / actual.r, colour.b / colour.r, 1e-5) << "the STF's colour at d = " << d;
    }
    for (int column : {86, 90, 100}) {
        const glm::vec4 outside = image.at(column, 64);
        EXPECT_EQ(outside.a, 0.0f) << "outside the sphere, column " << column;
    }
}

TEST(RayModeRender, SeveralIsoValuesCompositeNearestFirstWithTheirOpacities) {
    const Series series = densityCone();
    const glm::dvec2 centre(0.5, 0.5);
    Scene scene = orthographicSceneLookingDownZ(centre, 1.28, 128);
    scene.stf.curve.opacity = {{0.0, 0.02}};
    scene.stf.curve.color = {{0.0, {1.0, 0.0, 0.0}}, {0.5, {1.0, 0.0, 0.0}}, {0.6, {0.0, 0.0, 1.0}}};
    scene.finalMode = FinalMode::Stf;
    scene.rayMode = rayModeNamed("isosurface");
    // The outer shell (0.25, radius 0.3) at half opacity in front of the opaque inner one (0.75,
    // radius 0.1): blue behind red, each lit head-on at the axis.
    scene.rayOptions.values["values"] = std::vector<double>{0.75, 0.25};
    scene.rayOptions.values["opacities"] = std::vector<double>{1.0, 0.5};
    const Image image = renderSeries(series, scene);
    const glm::vec4 axis = image.at(64, 64);
    EXPECT_NEAR(axis.a, 1.0f, kTolerance);
    EXPECT_NEAR(axis.r, 0.5f, kTolerance) << "the outer shell, red, at half opacity";
    EXPECT_NEAR(axis.b, 0.5f, kTolerance) << "the inner sphere, blue, behind it";
    // Between the radii only the outer shell is met, twice: its front and its back, each at half
    // opacity.
    const glm::vec4 shellOnly = image.at(64 + 20, 64);
    EXPECT_NEAR(shellOnly.a, 0.75f, kTolerance);
    EXPECT_NEAR(shellOnly.b, 0.0f, kTolerance);
}

// A front advancing along x over three time-steps (density 1 behind x = 0.3, 0.5, 0.7), seen from
// above: first-arrival (threshold 0.5) gives each place the time-step the front reached it, and the
// 0.5 iso-surface, met where the ray comes in through the box's top face, shows that time-step's
// colour; where the front never came there is no value and no surface. Two samples (0.1) from
// each front the density is constant around the place, so the headlight there is full (nearer,
// the face is lit by the front's gradient, which lies across the view).
TEST(RayModeRender, IsosurfaceOfFirstArrivalShowsWhenTheFrontCame) {
    auto frontAt = [](double front) {
        BoxSpec box;
        box.dims = glm::ivec3(21);
        box.spacing = glm::dvec3(0.05);
        box.density = [front](glm::ivec3 sample) { return sample.x * 0.05 <= front + 1e-9 ? 1.0f : 0.0f; };
        return box;
    };
    const Series series = makeSeries({frontAt(0.3), frontAt(0.5), frontAt(0.7)});
    const glm::dvec2 centre(0.5, 0.5);
    Scene scene = orthographicSceneLookingDownZ(centre, 1.28, 128);
    scene.stf.curve = constantFunction({1.0, 1.0, 1.0}, 0.5);
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}, {2.0, {0, 0, 1}}};
    scene.finalMode = FinalMode::Modulate;
    scene.compositor = compositorNamed("first-arrival");
    scene.compositorOptions.values["threshold"] = 0.5;
    scene.rayMode = rayModeNamed("isosurface");
    scene.rayOptions.values["values"] = std::vector<double>{0.5};
    const Image image = renderSeries(series, scene);
    expectPixel(image, pixelOf({0.15, 0.5}, centre, 1.28, 128), {1, 0, 0, 1}, "reached in time-step 0");
    expectPixel(image, pixelOf({0.4, 0.5}, centre, 1.28, 128), {0, 1, 0, 1}, "reached in time-step 1");
    expectPixel(image, pixelOf({0.6, 0.5}, centre, 1.28, 128), {0, 0, 1, 1}, "reached in time-step 2");
    expectPixel(image, pixelOf({0.85, 0.5}, centre, 1.28, 128), glm::vec4(0.0f), "never reached");
}

TEST(RayModeRender, AModeThatComparesValuesIsRefusedWithACompositorThatHasNone) {
    const std::string text = R"({"dataset": "x/series.json", "compositor": "temporal-average", "ray": "maximum"})";
    try {
        parseScene(text, "scene.json");
        FAIL() << "temporal-average with the maximum was read";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("ray.mode"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("temporal-average"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace tstyles::testing
