// Transfer functions against closed-form answers: nodes, linear interpolation, ends, steps, gaps.
#include <gtest/gtest.h>

#include "tstyles/scene/transfer_function.h"

namespace {

using tstyles::ColorNode;
using tstyles::OpacityNode;
using tstyles::TransferFunction1D;

constexpr double tolerance = 1e-12;  // pure double arithmetic on a handful of values

void expectColor(const glm::dvec3& actual, const glm::dvec3& expected) {
    EXPECT_NEAR(actual.r, expected.r, tolerance);
    EXPECT_NEAR(actual.g, expected.g, tolerance);
    EXPECT_NEAR(actual.b, expected.b, tolerance);
}

TransferFunction1D twoNodeCurve() {
    TransferFunction1D curve;
    curve.opacity = {{0.2, 0.1}, {0.6, 0.9}};
    curve.color = {{0.2, {1.0, 0.0, 0.0}}, {0.6, {0.0, 0.0, 1.0}}};
    return curve;
}

TEST(TransferFunction, GivesTheNodeValuesAtTheNodes) {
    const TransferFunction1D curve = twoNodeCurve();
    EXPECT_NEAR(curve.evaluate(0.2).opacity, 0.1, tolerance);
    EXPECT_NEAR(curve.evaluate(0.6).opacity, 0.9, tolerance);
    expectColor(curve.evaluate(0.2).color, {1.0, 0.0, 0.0});
    expectColor(curve.evaluate(0.6).color, {0.0, 0.0, 1.0});
}

TEST(TransferFunction, InterpolatesLinearlyBetweenNodes) {
    const TransferFunction1D curve = twoNodeCurve();
    for (double x : {0.25, 0.35, 0.5, 0.59}) {
        const double t = (x - 0.2) / (0.6 - 0.2);
        EXPECT_NEAR(curve.evaluate(x).opacity, 0.1 + t * (0.9 - 0.1), tolerance) << "x = " << x;
        expectColor(curve.evaluate(x).color, {1.0 - t, 0.0, t});
    }
}

TEST(TransferFunction, HoldsTheEndValuesBeyondTheEnds) {
    const TransferFunction1D curve = twoNodeCurve();
    EXPECT_NEAR(curve.evaluate(0.0).opacity, 0.1, tolerance);
    EXPECT_NEAR(curve.evaluate(-5.0).opacity, 0.1, tolerance);
    EXPECT_NEAR(curve.evaluate(1.0).opacity, 0.9, tolerance);
    EXPECT_NEAR(curve.evaluate(42.0).opacity, 0.9, tolerance);
    expectColor(curve.evaluate(-1.0).color, {1.0, 0.0, 0.0});
    expectColor(curve.evaluate(2.0).color, {0.0, 0.0, 1.0});
}

TEST(TransferFunction, TwoNodesAtOnePositionMakeAStep) {
    TransferFunction1D curve;
    curve.opacity = {{0.0, 0.0}, {0.5, 0.2}, {0.5, 0.8}, {1.0, 1.0}};
    curve.color = {{0.5, {1.0, 0.0, 0.0}}, {0.5, {0.0, 1.0, 0.0}}};
    EXPECT_NEAR(curve.evaluate(0.25).opacity, 0.1, tolerance);
    EXPECT_NEAR(curve.evaluate(0.5 - 1e-9).opacity, 0.2, 1e-8);
    EXPECT_NEAR(curve.evaluate(0.5).opacity, 0.8, tolerance) << "at the step the later node wins";
    EXPECT_NEAR(curve.evaluate(0.75).opacity, 0.9, tolerance);
    expectColor(curve.evaluate(0.4).color, {1.0, 0.0, 0.0});
    expectColor(curve.evaluate(0.5).color, {0.0, 1.0, 0.0});
}

TEST(TransferFunction, AStepAtTheFirstPositionStartsThere) {
    TransferFunction1D curve;
    curve.opacity = {{0.0, 0.0}, {0.0, 1.0}};
    EXPECT_NEAR(curve.evaluate(-0.1).opacity, 0.0, tolerance);
    EXPECT_NEAR(curve.evaluate(0.0).opacity, 1.0, tolerance);
    EXPECT_NEAR(curve.evaluate(0.5).opacity, 1.0, tolerance);
}

TEST(TransferFunction, WithoutNodesIsTransparentWhite) {
    const TransferFunction1D empty;
    for (double x : {-1.0, 0.0, 0.5, 7.0}) {
        EXPECT_EQ(empty.evaluate(x).opacity, 0.0);
        expectColor(empty.evaluate(x).color, glm::dvec3(1.0));
    }
}

TEST(TransferFunction, ASingleNodeIsConstant) {
    TransferFunction1D curve;
    curve.opacity = {{0.3, 0.4}};
    curve.color = {{0.9, {0.2, 0.4, 0.6}}};
    for (double x : {-1.0, 0.3, 0.5, 2.0}) {
        EXPECT_NEAR(curve.evaluate(x).opacity, 0.4, tolerance);
        expectColor(curve.evaluate(x).color, {0.2, 0.4, 0.6});
    }
}

TEST(TransferFunction, UnsortedNodesEvaluateAsSorted) {
    TransferFunction1D curve;
    curve.opacity = {{1.0, 1.0}, {0.0, 0.0}};
    EXPECT_NEAR(curve.evaluate(0.25).opacity, 0.25, tolerance);
}

TEST(TransferFunction, SortNodesKeepsTheOrderOfAStep) {
    TransferFunction1D curve;
    curve.opacity = {{1.0, 1.0}, {0.5, 0.2}, {0.5, 0.8}, {0.0, 0.0}};
    curve.sortNodes();
    const std::vector<OpacityNode> expected{{0.0, 0.0}, {0.5, 0.2}, {0.5, 0.8}, {1.0, 1.0}};
    EXPECT_EQ(curve.opacity, expected);
}

TEST(TransferFunction, IndexTstfReadsTheCurveAtTheTimeStep) {
    tstyles::IndexTstf tstf;
    tstf.curve.opacity = {{0.0, 0.2}, {4.0, 1.0}};
    EXPECT_NEAR(tstf.atStep(0).opacity, 0.2, tolerance);
    EXPECT_NEAR(tstf.atStep(1).opacity, 0.4, tolerance);
    EXPECT_NEAR(tstf.atStep(9).opacity, 1.0, tolerance);
}

TEST(TransferFunctionGradientTstf, NormalizeMapsTheRangeToTheUnitIntervalAndClamps) {
    tstyles::GradientTstf tstf;
    tstf.rangeLow = 0.2;
    tstf.rangeHigh = 0.6;
    EXPECT_NEAR(tstf.normalize(0.4), 0.5, tolerance);
    EXPECT_NEAR(tstf.normalize(0.2), 0.0, tolerance);
    EXPECT_NEAR(tstf.normalize(0.6), 1.0, tolerance);
    EXPECT_EQ(tstf.normalize(0.0), 0.0);
    EXPECT_EQ(tstf.normalize(0.9), 1.0);
}

TEST(TransferFunctionDefaults, StfIsAWhiteRampAndTstfsAreOpaqueWhite) {
    const auto stf = tstyles::defaultStf().curve.evaluate(0.3);
    EXPECT_NEAR(stf.opacity, 0.3, tolerance);
    expectColor(stf.color, glm::dvec3(1.0));
    for (int step : {0, 3, 10}) {
        EXPECT_EQ(tstyles::defaultIndexTstf().atStep(step).opacity, 1.0);
        expectColor(tstyles::defaultIndexTstf().atStep(step).color, glm::dvec3(1.0));
    }
    const auto gradient = tstyles::defaultGradientTstf();
    EXPECT_EQ(gradient.curve.evaluate(0.7).opacity, 1.0);
    EXPECT_EQ(gradient.rangeLow, 0.0);
    EXPECT_EQ(gradient.rangeHigh, 1.0);
}

}  // namespace
