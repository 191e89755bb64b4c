// Drawing onto images in closed form (coverage, compositing), text through FreeType, and the legend:
// swatches of the exact time-step colours where the layout says, labelled with the data's dates.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "tstyles/annotate/scene_annotations.h"
#include "tstyles/core/errors.h"
#include "tstyles/scene/temporal_compositors.h"

namespace {

using namespace tstyles;

constexpr float kExact = 1e-6f;

TEST(Canvas, FillsWholePixelsExactlyAndEdgePixelsByTheirCoveredArea) {
    Image image(8, 8);
    Canvas canvas(image);
    canvas.fillRect({2, 2, 3, 2}, {1.0f, 0.5f, 0.25f, 1.0f});
    EXPECT_NEAR(image.at(2, 2).r, 1.0f, kExact);
    EXPECT_NEAR(image.at(4, 3).g, 0.5f, kExact);
    EXPECT_EQ(image.at(5, 2), glm::vec4(0.0f));
    EXPECT_EQ(image.at(2, 4), glm::vec4(0.0f));
    Image half(4, 4);
    Canvas halfCanvas(half);
    halfCanvas.fillRect({0.5, 0, 1, 1}, {1.0f, 1.0f, 1.0f, 1.0f});  // half of pixel 0, half of pixel 1
    EXPECT_NEAR(half.at(0, 0).a, 0.5f, kExact);
    EXPECT_NEAR(half.at(1, 0).a, 0.5f, kExact);
}

TEST(Canvas, CompositesOverPremultipliedPixels) {
    Image image(1, 1);
    image.set(0, 0, {0.2f, 0.4f, 0.0f, 0.5f});  // premultiplied
    Canvas canvas(image);
    canvas.blend(0, 0, 0.5f, {1.0f, 0.0f, 0.0f, 0.8f});  // alpha 0.4 after coverage
    const glm::vec4 expected = glm::vec4(0.4f, 0.0f, 0.0f, 0.4f) + glm::vec4(0.2f, 0.4f, 0.0f, 0.5f) * 0.6f;
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(image.at(0, 0)[c], expected[c], kExact);
}

TEST(Canvas, AOnePixelLineThroughPixelCentresCoversOneRow) {
    Image image(10, 5);
    Canvas canvas(image);
    canvas.drawLine({1.5, 2.5}, {8.5, 2.5}, 1.0, {1.0f, 1.0f, 1.0f, 1.0f});
    for (int x = 2; x <= 7; ++x) {
        EXPECT_NEAR(image.at(x, 2).a, 1.0f, kExact) << x;
        EXPECT_EQ(image.at(x, 1).a, 0.0f) << x;
        EXPECT_EQ(image.at(x, 3).a, 0.0f) << x;
    }
}

TEST(Font, DecodesUtf8AndDrawsAntiAliasedTextAsWideAsMeasured) {
    EXPECT_EQ(decodeUtf8("\xc2\xb0" "C"), (std::vector<char32_t>{0xB0, 'C'}));
    EXPECT_EQ(decodeUtf8("a\xff"), (std::vector<char32_t>{'a', 0xFFFD}));
    const Font font = Font::openDefault();
    Image image(200, 40);
    Canvas canvas(image);
    const std::string text = "12.3 \xc2\xb0" "C";
    canvas.drawText(font, text, {10, 28}, 16, {1.0f, 1.0f, 1.0f, 1.0f});
    int inkLeft = 200, inkRight = -1, partial = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 200; ++x) {
            const float a = image.at(x, y).a;
            if (a > 0.0f) inkLeft = std::min(inkLeft, x), inkRight = std::max(inkRight, x);
            if (a > 0.0f && a < 1.0f) ++partial;
        }
    EXPECT_GT(partial, 20);  // anti-aliased edges
    // Ink spans the advance less the side bearings of the first and last glyphs (a pixel or two).
    EXPECT_NEAR(inkRight + 1 - inkLeft, font.width(text, 16), 3.0);
    EXPECT_NEAR(inkLeft, 10, 2);
    // The degree sign has ink of its own, above the baseline, between "3 " and "C".
    Image degree(40, 40);
    Canvas degreeCanvas(degree);
    degreeCanvas.drawText(font, "\xc2\xb0", {10, 28}, 16, {1.0f, 1.0f, 1.0f, 1.0f});
    float ink = 0.0f;
    for (const float value : degree.rgba) ink += value;
    EXPECT_GT(ink, 5.0f);
}

TEST(Font, AMissingFontFileNamesIt) {
    try {
        Font font("/no/such/font.ttf");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("/no/such/font.ttf"), std::string::npos);
    }
}

// Four time-steps a day apart from 2005-09-01, on a tiny grid.
Series datedSeries() {
    Series series;
    series.name = "temperature";
    series.valueUnit = "degC";
    series.valueRange = {0.0, 30.0};
    series.time.unit = TimeUnit::Days;
    series.time.reference = CalendarDate{2005, 9, 1};
    RectilinearGrid grid;
    grid.dims = {2, 2, 2};
    for (int step = 0; step < 4; ++step) {
        TimeStep timeStep;
        timeStep.time = step;
        timeStep.grid = grid;
        timeStep.density.assign(8, 0.0f);
        series.steps.push_back(timeStep);
    }
    return series;
}

TEST(Legend, SwatchesShowTheTimeStepsColoursAndTheDataDates) {
    const Series series = datedSeries();
    Scene scene;
    scene.annotations.legend = true;
    scene.annotations.legendCorner = Corner::TopLeft;
    scene.finalMode = FinalMode::Tstf;  // the index TSTF alone: no STF bar
    const glm::dvec3 colours[] = {{0.1, 0.2, 0.9}, {0.2, 0.8, 0.3}, {0.9, 0.8, 0.1}, {0.9, 0.3, 0.1}};
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color.clear();
    for (int step = 0; step < 4; ++step) scene.indexTstf.curve.color.push_back({double(step), colours[step]});
    Image image(512, 512);
    const View view = resolveView(scene.camera, series.worldBounds(), 512, 512);
    const AnnotationLayout layout = drawAnnotations(image, scene, series, DisplayFrame{}, view, Font::openDefault());
    ASSERT_EQ(layout.stepSwatches.size(), 4u);
    EXPECT_EQ(layout.swatchLabels, (std::vector<std::string>{"2005-09-01", "2005-09-02", "2005-09-03", "2005-09-04"}));
    for (int step = 0; step < 4; ++step) {
        const Rect& swatch = layout.stepSwatches[std::size_t(step)];
        const glm::vec4 centre = image.at(int(swatch.x + swatch.width / 2), int(swatch.y + swatch.height / 2));
        // An opaque time-step's swatch is its colour, opaque, whatever the panel under it.
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], float(colours[step][c]), 1e-5f) << step << " " << c;
        EXPECT_NEAR(centre.a, 1.0f, 1e-5f);
        // Its label: ink to the right of the swatch, on its row.
        float ink = 0.0f;
        for (int x = int(swatch.right()) + 3; x < int(swatch.right()) + 60; ++x) ink += image.at(x, int(swatch.y + swatch.height / 2)).r;
        EXPECT_GT(ink, 1.0f) << step;
    }
    // The swatches lie in the legend panel, one under the other, apart.
    for (std::size_t i = 1; i < 4; ++i) EXPECT_GE(layout.stepSwatches[i].y, layout.stepSwatches[i - 1].bottom());
}

TEST(Legend, ManyTimeStepsBecomeAStripOfCellsThatDoNotOverlap) {
    Series series = datedSeries();
    while (series.steps.size() < 60) {
        series.steps.push_back(series.steps.back());
        series.steps.back().time += 1.0;
    }
    Scene scene;
    scene.annotations.legend = true;
    Image image(512, 512);
    const View view = resolveView(scene.camera, series.worldBounds(), 512, 512);
    const AnnotationLayout layout = drawAnnotations(image, scene, series, DisplayFrame{}, view, Font::openDefault());
    ASSERT_EQ(layout.stepSwatches.size(), 60u);
    for (std::size_t i = 1; i < 60; ++i) EXPECT_GE(layout.stepSwatches[i].x, layout.stepSwatches[i - 1].right() - 1e-9);
    for (const Rect& swatch : layout.stepSwatches) EXPECT_LE(swatch.right(), 512.0);
}

TEST(Legend, FollowsWhatReadsTheCompositor) {
    const Series series = datedSeries();
    for (const std::string& name : temporalCompositorNames()) {
        Scene scene;
        scene.annotations.legend = true;
        scene.finalMode = FinalMode::Tstf;  // the TSTF's legend alone
        scene.compositor = *temporalCompositorFromString(name);
        const TemporalCompositorInfo& info = compositorInfo(scene.compositor);
        Image image(512, 512);
        const View view = resolveView(scene.camera, series.worldBounds(), 512, 512);
        const AnnotationLayout layout = drawAnnotations(image, scene, series, DisplayFrame{}, view, Font::openDefault());
        // The time-steps' swatches for a compositor that picks or styles time-steps; the gradient
        // TSTF's bar (one panel) for one that computes a value.
        if (info.reads == CompositorReads::GradientTstf) {
            EXPECT_TRUE(layout.stepSwatches.empty()) << info.name;
            EXPECT_EQ(layout.panels.size(), 1u) << info.name;
        } else {
            EXPECT_EQ(layout.stepSwatches.size(), 4u) << info.name;
        }
    }
    // The scene's own code: what it says reads it.
    Scene custom;
    custom.annotations.legend = true;
    custom.finalMode = FinalMode::Tstf;
    custom.compositor = kCustomCompositor;
    custom.compositorOptions.custom = CustomCompositor{"return 0.0;", "scene.json", false, CompositorReads::GradientTstf};
    Image image(512, 512);
    const View view = resolveView(custom.camera, series.worldBounds(), 512, 512);
    EXPECT_TRUE(drawAnnotations(image, custom, series, DisplayFrame{}, view, Font::openDefault()).stepSwatches.empty());
}

TEST(Ticks, AreOneTwoOrFiveTimesAPowerOfTen) {
    EXPECT_DOUBLE_EQ(niceStep(10.0, 5), 2.0);
    EXPECT_DOUBLE_EQ(niceStep(0.37, 4), 0.1);
    EXPECT_DOUBLE_EQ(niceStep(1000.0, 2), 500.0);
    EXPECT_EQ(tickLabel(0.30000000000000004, 0.1), "0.3");
    EXPECT_EQ(tickLabel(-1000.0, 500.0), "-1000");
    EXPECT_EQ(tickLabel(2.5e7, 1e7), "2.5e+07");
}

}  // namespace
