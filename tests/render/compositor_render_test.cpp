// The temporal compositors of issue 16 on constant boxes, against closed-form values read back
// through a known transfer function: a linear gradient TSTF ramp turns a characteristic into a
// colour that says its value, an index TSTF with one colour per time-step says which time-step won.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "stacked_boxes.h"

namespace tstyles::testing {
namespace {

// Every sample opaque in the STF, the final image the TSTF alone: a pixel is the TSTF's colour.
Scene tstfScene(TemporalCompositor compositor) {
    Scene scene = orthographicSceneLookingDownZ(kStackCentre, kStackViewHeight, kStackSize);
    scene.stf.curve = constantFunction({1, 1, 1}, 1.0);
    scene.compositor = compositor;
    scene.finalMode = FinalMode::Tstf;
    return scene;
}

// Index TSTF: time-step 0 red, 1 green, 2 blue, all opaque.
void colourEachStep(Scene& scene) {
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}, {2.0, {0, 0, 1}}};
}

// Gradient TSTF over [low, high]: a linear ramp from green (low) to orange (high), opaque, so that
// the value v shows as (s, 1 - s / 2, 0) with s = (v - low) / (high - low).
void rampOver(Scene& scene, double low, double high) {
    scene.gradientTstf.curve.opacity = {{0.0, 1.0}};
    scene.gradientTstf.curve.color = {{0.0, {0, 1, 0}}, {1.0, {1, 0.5, 0}}};
    scene.gradientTstf.rangeLow = low;
    scene.gradientTstf.rangeHigh = high;
}

glm::vec4 rampColour(double value, double low, double high) {
    const double s = (value - low) / (high - low);
    return {float(s), float(1.0 - 0.5 * s), 0.0f, 1.0f};
}

TEST(CompositorRender, TemporalMinimumShowsTheLowestDensitysTimeStep) {
    const Series series = stackedBoxes({0.5f, 0.2f, 0.7f});
    Scene scene = tstfScene(compositorNamed("temporal-min"));
    colourEachStep(scene);
    expectStackPixel(renderSeries(series, scene), kStackCentre, kGreen, "time-step 1 is lowest");
    // Where the lowest density is transparent in the STF, nothing shows: what persists through
    // the whole series, not the most visible time-step.
    scene.stf.curve.opacity = {{0.0, 0.0}, {0.29, 0.0}, {0.3, 1.0}};
    expectStackPixel(renderSeries(series, scene), kStackCentre, kTransparent, "the lowest is below the STF");
}

TEST(CompositorRender, TimeOfMaximumShowsTheHighestDensitysTimeStepWhateverItsOpacity) {
    // The STF makes dense samples fainter, so the most opaque time-step (temporal MIP's) is the
    // least dense one: time-of-max still picks the densest.
    const Series series = stackedBoxes({0.3f, 0.8f, 0.5f});
    Scene scene = tstfScene(compositorNamed("time-of-max"));
    scene.stf.curve.opacity = {{0.0, 1.0}, {1.0, 0.1}};
    colourEachStep(scene);
    expectStackPixel(renderSeries(series, scene), kStackCentre, kGreen, "time-step 1 is densest");
    scene.compositor = compositorNamed("temporal-mip");
    expectStackPixel(renderSeries(series, scene), kStackCentre, kRed, "temporal MIP: time-step 0 is most opaque");
    // A tie goes to the earlier time-step.
    scene.compositor = compositorNamed("time-of-max");
    expectStackPixel(renderSeries(stackedBoxes({0.8f, 0.3f, 0.8f}), scene), kStackCentre, kRed, "tie: time-step 0");
}

TEST(CompositorRender, FirstArrivalShowsTheFirstTimeStepAtTheThreshold) {
    const Series series = stackedBoxes({0.2f, 0.6f, 0.9f});
    Scene scene = tstfScene(compositorNamed("first-arrival"));
    colourEachStep(scene);
    scene.compositorOptions.values["threshold"] = 0.5;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kGreen, "0.6 >= 0.5 first at time-step 1");
    scene.compositorOptions.values["threshold"] = 0.9;  // "at or above"
    expectStackPixel(renderSeries(series, scene), kStackCentre, kBlue, "0.9 reaches 0.9 at time-step 2");
    scene.compositorOptions.values["threshold"] = 0.1;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kRed, "every time-step reaches 0.1");
    scene.compositorOptions.values["threshold"] = 0.95;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kTransparent, "none reaches 0.95");
}

TEST(CompositorRender, LastAboveShowsTheLastTimeStepAtTheThreshold) {
    const Series series = stackedBoxes({0.9f, 0.6f, 0.2f});
    Scene scene = tstfScene(compositorNamed("last-above"));
    colourEachStep(scene);
    scene.compositorOptions.values["threshold"] = 0.5;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kGreen, "0.6 >= 0.5 last at time-step 1");
    scene.compositorOptions.values["threshold"] = 0.1;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kBlue, "every time-step reaches 0.1");
    scene.compositorOptions.values["threshold"] = 0.95;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kTransparent, "none reaches 0.95");
}

TEST(CompositorRender, ThresholdCrossingShowsTheFirstCrossingInItsDirection) {
    // Against 0.5: above from the start (first-arrival picks time-step 0), falls at 1, rises at 2.
    const Series series = stackedBoxes({0.6f, 0.2f, 0.7f});
    Scene scene = tstfScene(compositorNamed("threshold-crossing"));
    colourEachStep(scene);
    // Transparent below the threshold: a falling crossing shows as the time-step before it does.
    scene.stf.curve.opacity = {{0.0, 0.0}, {0.49, 0.0}, {0.5, 1.0}};
    scene.compositorOptions.values["threshold"] = 0.5;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kBlue, "rising (the default): 0.2 -> 0.7 at 2");
    scene.compositorOptions.values["direction"] = std::string("falling");
    expectStackPixel(renderSeries(series, scene), kStackCentre, kGreen, "falling: 0.6 -> 0.2 at 1, shown as 0.6");
    scene.compositorOptions.values["threshold"] = 0.1;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kTransparent, "always above 0.1: no crossing");
    scene.compositorOptions.values["direction"] = std::string("rising");
    scene.compositorOptions.values["threshold"] = 0.65;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kBlue, "0.6 is below 0.65: rises at 2 only");
    scene.compositorOptions.values["threshold"] = 0.1;
    expectStackPixel(renderSeries(series, scene), kStackCentre, kTransparent, "never below 0.1: no rise");
}

TEST(CompositorRender, StandardDeviationOfKnownDensities) {
    const std::vector<float> densities{0.2f, 0.4f, 0.9f};
    const Series series = stackedBoxes(densities);
    double mean = 0.0;
    for (float d : densities) mean += d / 3.0;
    double variance = 0.0;
    for (float d : densities) variance += (d - mean) * (d - mean) / 3.0;  // population: divided by n
    const double deviation = std::sqrt(variance);                         // 0.2944
    Scene scene = tstfScene(compositorNamed("temporal-std-dev"));
    rampOver(scene, 0.0, 0.5);
    expectStackPixel(renderSeries(series, scene), kStackCentre, rampColour(deviation, 0.0, 0.5), "standard deviation");
}

TEST(CompositorRender, LinearTrendIsTheSlopeOverTheTimeStamps) {
    Scene scene = tstfScene(compositorNamed("linear-trend"));
    // Densities 0.2, 0.4, 0.6 at times 0, 1, 2: 0.2 per unit time, the middle of [0, 0.4].
    rampOver(scene, 0.0, 0.4);
    expectStackPixel(renderSeries(stackedBoxes({0.2f, 0.4f, 0.6f}), scene), kStackCentre, {0.5f, 0.75f, 0.0f, 1.0f},
                "slope 0.2");
    // Falling: -0.2 per unit time on the signed range [-0.4, 0.4].
    rampOver(scene, -0.4, 0.4);
    expectStackPixel(renderSeries(stackedBoxes({0.6f, 0.4f, 0.2f}), scene), kStackCentre, rampColour(-0.2, -0.4, 0.4),
                "slope -0.2");
    // Uneven stamps far from 0: the least-squares slope over the stamps, not over the indices.
    Series uneven = stackedBoxes({0.2f, 0.4f, 0.6f});
    const double times[3] = {1000.0, 1002.0, 1006.0};
    for (int i = 0; i < 3; ++i) uneven.steps[std::size_t(i)].time = times[i];
    const double meanTime = (times[0] + times[1] + times[2]) / 3.0;
    const double densities[3] = {0.2, 0.4, 0.6};
    double covariance = 0.0, timeVariance = 0.0;
    for (int i = 0; i < 3; ++i) {
        covariance += (times[i] - meanTime) * (densities[i] - 0.4);
        timeVariance += (times[i] - meanTime) * (times[i] - meanTime);
    }
    expectStackPixel(renderSeries(uneven, scene), kStackCentre, rampColour(covariance / timeVariance, -0.4, 0.4),
                "slope over uneven stamps (0.0643)");
}

TEST(CompositorRender, DifferenceOfTwoChosenTimeStepsIsSigned) {
    // Time-steps 0 and 1 over the origin, time-step 2 shifted by half a box: it overlaps them in
    // x in [0.35, 0.7].
    const Series series =
        makeSeries({constantBox({0, 0, 0}, 0.7f), constantBox({0, 0, 0}, 0.4f), constantBox({0.35, 0, 0}, 0.2f)});
    Scene scene = tstfScene(compositorNamed("difference"));
    rampOver(scene, -1.0, 1.0);
    const glm::dvec2 overlap(0.525, 0.35);
    const glm::dvec2 withoutStep2(0.15, 0.35);
    // No steps given: from the first time-step to the last, density(2) - density(0) = -0.5.
    const Image firstToLast = renderSeries(series, scene);
    expectStackPixel(firstToLast, overlap, rampColour(-0.5, -1.0, 1.0), "0.2 - 0.7");
    expectStackPixel(firstToLast, withoutStep2, kTransparent, "time-step 2 has no data there");
    scene.compositorOptions.values["steps"] = TimeStepPair{2, 1};
    const Image backwards = renderSeries(series, scene);
    expectStackPixel(backwards, overlap, rampColour(0.2, -1.0, 1.0), "0.4 - 0.2");
    scene.compositorOptions.values["steps"] = TimeStepPair{0, 1};
    expectStackPixel(renderSeries(series, scene), withoutStep2, rampColour(-0.3, -1.0, 1.0), "0.4 - 0.7");
}

// Chronovolume: per sample, the time-steps' styled colours (STF times index TSTF) composited front
// to back in time order; the sample then attenuates along the ray like any other.
glm::vec4 chronovolumePixel(const std::vector<glm::dvec4>& styledInTimeOrder, double thickness) {
    glm::dvec4 accumulated(0.0);  // premultiplied
    for (const glm::dvec4& styled : styledInTimeOrder)
        accumulated += (1.0 - accumulated.a) * glm::dvec4(glm::dvec3(styled) * styled.a, styled.a);
    const glm::dvec3 sampleColour = glm::dvec3(accumulated) / accumulated.a;
    const double alpha = slabOpacity(accumulated.a, thickness);
    return glm::vec4(glm::vec3(sampleColour * alpha), float(alpha));
}

TEST(CompositorRender, ChronovolumeCompositesTheTimeStepsInTimeOrder) {
    // Time-step 0 (density 0.5) red, time-step 1 (density 1) blue; the STF gives opacity 0.2 x
    // density: 0.1 and 0.2 per reference length.
    const Series series = stackedBoxes({0.5f, 1.0f});
    Scene scene = orthographicSceneLookingDownZ(kStackCentre, kStackViewHeight, kStackSize);
    scene.stf.curve.opacity = {{0.0, 0.0}, {1.0, 0.2}};
    scene.stf.curve.color = {{0.0, {1, 1, 1}}};
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 0, 1}}};
    scene.finalMode = FinalMode::Modulate;
    scene.compositor = compositorNamed("chronovolume");
    const glm::dvec4 red(1, 0, 0, 0.1);
    const glm::dvec4 blue(0, 0, 1, 0.2);
    expectStackPixel(renderSeries(series, scene), kStackCentre, chronovolumePixel({red, blue}, kConstantBoxWidth),
                "red in front of blue");
    // The order is time's, not the boxes': with the densities swapped, blue (time-step 1) is
    // still composited behind the now fainter red.
    const glm::dvec4 fainterBlue(0, 0, 1, 0.1);
    const glm::dvec4 strongerRed(1, 0, 0, 0.2);
    expectStackPixel(renderSeries(stackedBoxes({1.0f, 0.5f}), scene), kStackCentre,
                chronovolumePixel({strongerRed, fainterBlue}, kConstantBoxWidth), "stronger red in front");
}

// Styles inside the masks only (an STF without styles, a styled index TSTF, modulate): a sample's
// time-step inside its mask reads a lit sphere, one outside does not, so the temporal average and
// the chronovolume style the first and colour the second without style code (tc_average.glsl,
// tc_chronovolume.glsl). Time-step 0 (density 0.5) lies inside its mask, time-step 1 (density 1)
// outside its own; the STF is white with opacity 0.2 x density, the index TSTF one flat style.
class StylesInsideTheMasksOnly : public ::testing::Test {
protected:
    static constexpr glm::vec4 kStyleColour{0.2f, 0.6f, 0.4f, 1.0f};  // exact in 8 bits

    static Series maskedBoxes() {
        BoxSpec inside = constantBox({0, 0, 0}, 0.5f);
        inside.mask = [](glm::ivec3) { return true; };
        BoxSpec outside = constantBox({0, 0, 0}, 1.0f);
        outside.mask = [](glm::ivec3) { return false; };
        return makeSeries({inside, outside});
    }

    static Scene maskedStyleScene(TemporalCompositor compositor) {
        Scene scene = orthographicSceneLookingDownZ(kStackCentre, kStackViewHeight, kStackSize);
        scene.stf.curve.opacity = {{0.0, 0.0}, {1.0, 0.2}};
        scene.stf.curve.color = {{0.0, {1, 1, 1}}};
        const std::string style = writeStyle("flat-for-masks", 16, 16, [](glm::vec2) { return kStyleColour; });
        scene.indexTstf.curve.opacity = {{0.0, 1.0}};
        scene.indexTstf.curve.color = {{0.0, {1, 1, 1}, style, 0}};
        scene.finalMode = FinalMode::Modulate;
        scene.compositor = compositor;
        return scene;
    }

    // Time-step 0 inside its mask: the STF (white, 0.1) modulated by the styled TSTF; time-step 1
    // outside: the STF alone (white, 0.2).
    const glm::dvec4 styledInside{kStyleColour.r, kStyleColour.g, kStyleColour.b, 0.1};
    const glm::dvec4 plainOutside{1, 1, 1, 0.2};
};

TEST_F(StylesInsideTheMasksOnly, TheTemporalAverageAveragesTheStyledAndThePlainTimeStep) {
    // Colours weighted by opacity, opacities averaged.
    const double opacity = (styledInside.a + plainOutside.a) / 2.0;
    const glm::dvec3 colour = (glm::dvec3(styledInside) * styledInside.a + glm::dvec3(plainOutside) * plainOutside.a) /
                              (styledInside.a + plainOutside.a);
    const double alpha = slabOpacity(opacity, kConstantBoxWidth);
    expectStackPixel(renderSeries(maskedBoxes(), maskedStyleScene(compositorNamed("temporal-average"))), kStackCentre,
                glm::vec4(glm::vec3(colour * alpha), float(alpha)), "styled inside, plain outside");
}

TEST_F(StylesInsideTheMasksOnly, TheChronovolumeCompositesTheStyledBeforeThePlainTimeStep) {
    expectStackPixel(renderSeries(maskedBoxes(), maskedStyleScene(compositorNamed("chronovolume"))), kStackCentre,
                chronovolumePixel({styledInside, plainOutside}, kConstantBoxWidth), "styled in front of plain");
}

}  // namespace
}  // namespace tstyles::testing
