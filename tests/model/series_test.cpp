// Series geometry against known answers: value-type names, placement, world bounds, spacing.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "tstyles/data/series.h"

namespace {

using tstyles::ValueType;

constexpr double kTolerance = 1e-12;  // a handful of double roundings in a 4x4 product

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected) {
    EXPECT_NEAR(actual.x, expected.x, kTolerance);
    EXPECT_NEAR(actual.y, expected.y, kTolerance);
    EXPECT_NEAR(actual.z, expected.z, kTolerance);
}

tstyles::TimeStep stepOn(glm::ivec3 dims, glm::dvec3 spacing, tstyles::Placement placement = {}) {
    tstyles::TimeStep step;
    step.grid = tstyles::RectilinearGrid{dims, spacing};
    step.placement = placement;
    return step;
}

TEST(ValueType, NamesRoundTripAndSizesAreKnown) {
    for (ValueType type : {ValueType::UInt8, ValueType::UInt16, ValueType::Float32, ValueType::Int8,
                           ValueType::Int16, ValueType::Int32, ValueType::Float64}) {
        EXPECT_EQ(tstyles::valueTypeFromString(tstyles::toString(type)), type);
    }
    EXPECT_EQ(tstyles::toString(ValueType::UInt16), "uint16");
    EXPECT_EQ(tstyles::valueTypeFromString("int64"), std::nullopt);
    EXPECT_EQ(tstyles::bytesPerValue(ValueType::UInt8), 1u);
    EXPECT_EQ(tstyles::bytesPerValue(ValueType::UInt16), 2u);
    EXPECT_EQ(tstyles::bytesPerValue(ValueType::Float32), 4u);
    EXPECT_EQ(tstyles::bytesPerValue(ValueType::Int8), 1u);
    EXPECT_EQ(tstyles::bytesPerValue(ValueType::Int16), 2u);
    EXPECT_EQ(tstyles::bytesPerValue(ValueType::Int32), 4u);
    EXPECT_EQ(tstyles::bytesPerValue(ValueType::Float64), 8u);
}

TEST(Placement, GridToWorldRotatesThenTranslates) {
    tstyles::Placement placement;
    placement.origin = {1.0, 2.0, 3.0};
    placement.rotation = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 0, 1));
    const glm::dvec3 world(placement.gridToWorld() * glm::dvec4(1.0, 0.0, 0.0, 1.0));
    expectNear(world, {1.0, 3.0, 3.0});
    EXPECT_EQ(tstyles::Placement{}.gridToWorld(), glm::dmat4(1.0));
}

TEST(AxisAngle, ConvertsBothWays) {
    const auto identity = tstyles::toAxisAngle(glm::dquat(1.0, 0.0, 0.0, 0.0));
    EXPECT_EQ(identity.axis, glm::dvec3(0, 0, 1));
    EXPECT_EQ(identity.angleDeg, 0.0);

    const glm::dvec3 axis = glm::normalize(glm::dvec3(1, 2, -2));
    const auto converted = tstyles::toAxisAngle(glm::angleAxis(glm::radians(40.0), axis));
    EXPECT_NEAR(converted.angleDeg, 40.0, kTolerance);
    expectNear(converted.axis, axis);

    // -q is the same rotation; it must still come back with an angle in [0, 180].
    const auto negated = tstyles::toAxisAngle(-glm::angleAxis(glm::radians(40.0), axis));
    EXPECT_NEAR(negated.angleDeg, 40.0, kTolerance);
    expectNear(negated.axis, axis);

    const glm::dquat back = tstyles::fromAxisAngle({glm::dvec3(0, 0, 3), 90.0});
    EXPECT_NEAR(glm::dot(back, glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 0, 1))), 1.0, kTolerance);
}

TEST(SeriesBounds, UnrotatedGridSpansDimsMinusOneTimesSpacing) {
    tstyles::Series series;
    tstyles::Placement placement;
    placement.origin = {1.0, -1.0, 0.5};
    series.steps.push_back(stepOn({3, 5, 2}, {0.5, 0.25, 2.0}, placement));
    const auto bounds = series.worldBounds(0);
    expectNear(bounds.lower, {1.0, -1.0, 0.5});
    expectNear(bounds.upper, {2.0, 0.0, 2.5});
}

TEST(SeriesBounds, RotatedGridBoundsEncloseTheTurnedCorners) {
    tstyles::Series series;
    tstyles::Placement quarterTurn;
    quarterTurn.origin = {10.0, 0.0, 0.0};
    quarterTurn.rotation = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 0, 1));
    // Extent (2, 1, 1); a quarter turn about z sends x to y and y to -x.
    series.steps.push_back(stepOn({3, 2, 2}, {1.0, 1.0, 1.0}, quarterTurn));
    expectNear(series.worldBounds(0).lower, {9.0, 0.0, 0.0});
    expectNear(series.worldBounds(0).upper, {10.0, 2.0, 1.0});

    tstyles::Placement eighthTurn;
    eighthTurn.rotation = glm::angleAxis(glm::radians(45.0), glm::dvec3(0, 0, 1));
    // A unit square turned by 45 degrees spans sqrt(2) in x, centred on x = 0, and sqrt(2) in y.
    series.steps.push_back(stepOn({2, 2, 2}, {1.0, 1.0, 1.0}, eighthTurn));
    const double half = std::sqrt(0.5);
    expectNear(series.worldBounds(1).lower, {-half, 0.0, 0.0});
    expectNear(series.worldBounds(1).upper, {half, 2.0 * half, 1.0});

    // The whole series is the union of both.
    expectNear(series.worldBounds().lower, {-half, 0.0, 0.0});
    expectNear(series.worldBounds().upper, {10.0, 2.0, 1.0});
}

TEST(Series, FinestSpacingIsTheSmallestComponentOfAnyStep) {
    tstyles::Series series;
    series.steps.push_back(stepOn({2, 2, 2}, {0.5, 0.3, 0.4}));
    series.steps.push_back(stepOn({2, 2, 2}, {0.2, 0.6, 0.25}));
    EXPECT_EQ(series.finestSpacing(), 0.2);
    EXPECT_THROW(tstyles::Series{}.finestSpacing(), std::logic_error);
}

TEST(Series, HasMasksWhenAnyStepHasOne) {
    tstyles::Series series;
    series.steps.push_back(stepOn({2, 2, 2}, {1, 1, 1}));
    series.steps.push_back(stepOn({2, 2, 2}, {1, 1, 1}));
    EXPECT_FALSE(series.hasMasks());
    series.steps[1].mask = std::vector<std::uint8_t>(8, 1);
    EXPECT_TRUE(series.hasMasks());
}

}  // namespace
