// The probe's pictures (probe_plot.h): each cell of a Hovmoeller diagram has the ramp's colour of
// its value's place in the range, missing cells are grey, and a line plot's markers sit where
// their values do.
#include <gtest/gtest.h>

#include "tstyles/annotate/probe_plot.h"

namespace tstyles {
namespace {

ProbeTable lineOfThree() {
    ProbeTable table;
    table.title = "f along a line";
    table.unit = "K";
    table.times = {0.0, 1.0};
    table.timeLabels = {"0", "1"};
    table.distances = {0.0, 1.0, 2.0};
    // Per place, per time-step: the range is 10 to 30; one value is missing.
    table.values = {{10.0, 20.0}, {15.0, std::nullopt}, {25.0, 30.0}};
    return table;
}

// One place over the time-steps 0, 1, 2 (labels "0", "1", "2") with `values`.
ProbeTable placeOverThreeTimes(const std::vector<std::optional<double>>& values) {
    ProbeTable table;
    table.title = "f at a place";
    table.times = {0.0, 1.0, 2.0};
    table.timeLabels = {"0", "1", "2"};
    table.distances = {0.0};
    table.values = {values};
    return table;
}

void expectColour(const Image& image, int x, int y, const glm::vec3& expected) {
    const glm::vec4 pixel = image.at(x, y);
    EXPECT_NEAR(pixel.r, expected.r, 1e-6) << x << ", " << y;
    EXPECT_NEAR(pixel.g, expected.g, 1e-6) << x << ", " << y;
    EXPECT_NEAR(pixel.b, expected.b, 1e-6) << x << ", " << y;
    EXPECT_FLOAT_EQ(pixel.a, 1.0f);
}

TEST(ProbePlot, HovmoellerCellsTakeTheRampColourOfTheirValue) {
    const Image image = drawProbePlot(lineOfThree(), {800, 450});
    // The plot spans x 90 to 690 and y 44 to 394 (probe_plot.cpp): three columns of 200 pixels,
    // two rows of 175; a cell's centre is well inside it.
    expectColour(image, 190, 131, probeRampColour(0.0));   // 10 at place 0, time 0
    expectColour(image, 390, 131, probeRampColour(0.25));  // 15
    expectColour(image, 590, 131, probeRampColour(0.75));  // 25
    expectColour(image, 190, 306, probeRampColour(0.5));   // 20 at place 0, time 1
    expectColour(image, 590, 306, probeRampColour(1.0));   // 30
    expectColour(image, 390, 306, glm::vec3(0.30f, 0.30f, 0.32f));  // missing: grey
}

TEST(ProbePlot, TheRampRisesFromDarkBlueToYellow) {
    EXPECT_NEAR(probeRampColour(0.0).b, 0.329f, 1e-6);
    EXPECT_NEAR(probeRampColour(1.0).r, 0.993f, 1e-6);
    // Lightness (luma) rises along the ramp.
    double previous = -1.0;
    for (int step = 0; step <= 20; ++step) {
        const glm::vec3 colour = probeRampColour(step / 20.0);
        const double luma = 0.2126 * colour.r + 0.7152 * colour.g + 0.0722 * colour.b;
        EXPECT_GT(luma, previous) << step;
        previous = luma;
    }
    EXPECT_EQ(probeRampColour(-1.0), probeRampColour(0.0));
    EXPECT_EQ(probeRampColour(2.0), probeRampColour(1.0));
}

TEST(ProbePlot, ALinePlotMarksEachValueAtItsTimeAndHeight) {
    const ProbeTable table = placeOverThreeTimes({0.0, std::nullopt, 10.0});
    const Image image = drawProbePlot(table, {800, 450});
    // The plot spans x 80 to 776 and y 44 to 394: time 0 at x 80, time 2 at x 776; value 0 at the
    // bottom, 10 at the top. The markers are 6 pixels square in the curve's colour.
    const glm::vec3 curve{0.98f, 0.74f, 0.25f};
    expectColour(image, 81, 392, curve);
    expectColour(image, 775, 45, curve);
    // No marker at time 1 (x 428) halfway up: missing values leave a gap.
    const glm::vec4 gap = image.at(428, 219);
    EXPECT_LT(gap.r, 0.5f);
}

// With the time-steps' colours (the index TSTF's), each marker is its time-step's colour inside a
// dark rim, 8 pixels square inside 10.
TEST(ProbePlot, ALinePlotsMarkersTakeTheirTimeStepsColours) {
    ProbeTable table = placeOverThreeTimes({0.0, 5.0, 10.0});
    table.timeColours = {{0.13f, 0.29f, 0.75f}, {0.95f, 0.95f, 0.95f}, {0.9f, 0.45f, 0.05f}};
    const Image image = drawProbePlot(table, {800, 450});
    // As above: time 0 at x 80, time 1 at x 428, time 2 at x 776; values 0, 5 and 10 at y 394, 219
    // and 44.
    expectColour(image, 82, 392, table.timeColours[0]);
    expectColour(image, 428, 219, table.timeColours[1]);
    expectColour(image, 774, 46, table.timeColours[2]);
    expectColour(image, 428 - 5, 219 - 5, {0.05f, 0.05f, 0.05f});  // the rim
}

}  // namespace
}  // namespace tstyles
