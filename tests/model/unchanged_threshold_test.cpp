// The automatic unchanged-place threshold (temporal_change.h): the noise of a place told apart from
// real change, the range that noise alone reaches, and the fitted threshold on series whose answer
// is known.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/temporal_change.h"

namespace tstyles {
namespace {

// Places of `count` independent Gaussian values of standard deviation `sigma` around 0.5, from a
// fixed seed.
std::vector<std::vector<double>> noisyPlaces(std::size_t places, std::size_t count, double sigma) {
    std::mt19937 random(20261129u);
    std::normal_distribution<double> noise(0.0, sigma);
    std::vector<std::vector<double>> result(places, std::vector<double>(count));
    for (auto& place : result)
        for (double& value : place) value = 0.5 + noise(random);
    return result;
}

Stf everythingVisible() {
    Stf stf;
    stf.curve.opacity = {{0.0, 1.0}};
    return stf;
}

TEST(UnchangedThreshold, NoiseRangeQuantileMatchesTheStudentizedRangeTables) {
    // Two values: the range is |N(0, 2)|, exceeded with probability 0.01 beyond 2.5758 sqrt 2.
    EXPECT_NEAR(noiseRangeQuantile(2), 2.5758 * std::sqrt(2.0), 2e-3);
    // The studentized range's 1 % points for infinite degrees of freedom (Harter 1960): 4.12 for
    // 3 values, 4.60 for 5, 5.16 for 10 (tables to two decimals).
    EXPECT_NEAR(noiseRangeQuantile(3), 4.12, 6e-3);
    EXPECT_NEAR(noiseRangeQuantile(5), 4.60, 6e-3);
    EXPECT_NEAR(noiseRangeQuantile(10), 5.16, 6e-3);
    EXPECT_EQ(noiseRangeQuantile(1), 0.0);
}

TEST(UnchangedThreshold, RealChangeIsNotCalledNoise) {
    // A body passing once (an event), a body staying for a while, a steady trend: no noise at all.
    EXPECT_EQ(noiseOfPlace({0, 0, 0, 1, 0, 0, 0, 0}), 0.0);
    EXPECT_EQ(noiseOfPlace({0, 0, 1, 1, 1, 0, 0, 0}), 0.0);
    EXPECT_NEAR(noiseOfPlace({0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7}), 0.0, 1e-12);
    // A seasonal cycle of amplitude 1 over 12 months is smooth: its fourth differences are
    // (2 sin(pi / 12))^4 = 0.072 of the amplitude at most, and their median over 5.64 is 0.0106
    // (the second differences alone said 0.11, and a tie of 3.64 times that, 0.4, is three times
    // what the peak month leads its neighbours by: 1 - cos(30 degrees) = 0.134).
    std::vector<double> season;
    for (int month = 0; month < 12; ++month) season.push_back(std::sin(2.0 * M_PI * (month + 0.5) / 12.0));
    EXPECT_NEAR(noiseOfPlace(season), 0.0106, 0.0005);
    EXPECT_LT(noiseRangeQuantile(2) * noiseOfPlace(season), 0.134 / 3.0) << "the peak month is not a tie";
}

TEST(UnchangedThreshold, GaussianNoiseIsMeasured) {
    // The median over many places of the smallest of four estimates: low (0.90 sigma over 40 000
    // simulated places of 40 values); within 10 % of that.
    const double sigma = 0.02;
    PlaceChanges places;
    for (const auto& place : noisyPlaces(2000, 40, sigma)) addChange(place, everythingVisible(), places);
    ASSERT_EQ(places.noises.size(), 2000u);
    std::vector<double> noises = places.noises;
    std::nth_element(noises.begin(), noises.begin() + 1000, noises.end());
    EXPECT_NEAR(noises[1000], 0.90 * sigma, 0.10 * 0.90 * sigma);
    // The threshold sits where noise alone rarely reaches: 1 % of the places would exceed it with
    // the noise known; with the estimate's 10 % low bias, 5.35 % of these 2000 do.
    const UnchangedFit fit = unchangedFitOf(places, 40);
    const auto exceeding = std::count_if(places.changes.begin(), places.changes.end(),
                                         [&](double change) { return change > fit.below; });
    EXPECT_LE(double(exceeding) / double(places.changes.size()), 0.06) << "threshold " << fit.below;
    // A tie: what noise puts between two equal values at most once in a hundred, 3.64 sigma.
    EXPECT_NEAR(fit.tie, 0.90 * noiseRangeQuantile(2) * sigma, 0.10 * 0.90 * noiseRangeQuantile(2) * sigma);
    EXPECT_NEAR(fit.below / fit.tie, noiseRangeQuantile(40) / noiseRangeQuantile(2), 1e-9);
}

TEST(UnchangedThreshold, ShortSeriesHaveTheirNoiseMeasuredToo) {
    // Two values: |difference| / 0.954 is unbiased; four: the smaller of two estimates of three and
    // two differences, 0.869 sigma (200 000 simulated places). Within 10 %.
    const double sigma = 0.02;
    for (const auto& [count, expected] : {std::pair{std::size_t(2), 1.0}, std::pair{std::size_t(4), 0.869}}) {
        PlaceChanges places;
        for (const auto& place : noisyPlaces(4000, count, sigma)) addChange(place, everythingVisible(), places);
        std::vector<double> noises = places.noises;
        std::nth_element(noises.begin(), noises.begin() + 2000, noises.end());
        EXPECT_NEAR(noises[2000], expected * sigma, 0.10 * expected * sigma) << count << " values";
    }
}

TEST(UnchangedThreshold, NoisierValuesHaveTheirOwnThresholds) {
    // Soft tissue around density 0.2 with noise 0.01, bone around 0.8 with noise 0.04 (a CT's): each
    // band takes its own places' noise (each estimate within 10 % of 0.90 sigma, as above); a band
    // without places takes the median of all.
    PlaceChanges places;
    const std::size_t count = 40;
    for (auto place : noisyPlaces(600, count, 0.01)) {
        for (double& value : place) value -= 0.3;
        addChange(place, everythingVisible(), places);
    }
    for (auto place : noisyPlaces(400, count, 0.04)) {
        for (double& value : place) value += 0.3;
        addChange(place, everythingVisible(), places);
    }
    const UnchangedFit fit = unchangedFitOf(places, count);
    ASSERT_EQ(fit.belowByDensity.size(), std::size_t(kUnchangedDensityBands));
    // Three time-steps are too few to tell a band's noise from a step: every band the median's.
    const UnchangedFit fromThree = unchangedFitOf(places, 3);
    EXPECT_EQ(fromThree.belowByDensity[std::size_t(unchangedDensityBand(0.8))], fromThree.below);
    const double quantile = noiseRangeQuantile(count);
    const auto expectBand = [&](double density, double sigma) {
        const auto band = std::size_t(unchangedDensityBand(density));
        EXPECT_NEAR(fit.belowByDensity[band], 0.90 * sigma * quantile, 0.10 * sigma * quantile) << density;
        EXPECT_NEAR(fit.tieByDensity[band], 0.90 * sigma * noiseRangeQuantile(2), 0.10 * sigma * 3.64) << density;
    };
    expectBand(0.2, 0.01);
    expectBand(0.8, 0.04);
    // The median of all places (in the upper part of soft tissue's, 600 of 1000) is the summary's
    // and the empty bands'.
    EXPECT_EQ(fit.belowByDensity[std::size_t(unchangedDensityBand(0.5))], fit.below);
    EXPECT_GT(fit.below, fit.belowByDensity[std::size_t(unchangedDensityBand(0.2))]);
    EXPECT_LT(fit.below, fit.belowByDensity[std::size_t(unchangedDensityBand(0.8))]);
}

TEST(UnchangedThreshold, ATenthOfTheTypicalLargestChangeWithoutNoise) {
    // Places that never change and places an event passes (change 0.6): 0.1 * 0.6.
    PlaceChanges places;
    for (int i = 0; i < 100; ++i) addChange({0.3, 0.3, 0.3, 0.3, 0.3, 0.3}, everythingVisible(), places);
    for (int i = 0; i < 20; ++i) addChange({0.3, 0.3, 0.9, 0.3, 0.3, 0.3}, everythingVisible(), places);
    EXPECT_NEAR(unchangedFitOf(places, 6).below, 0.06, 1e-12);
    EXPECT_EQ(unchangedFitOf(places, 6).tie, 0.0);  // no noise: only exact ties
    // Nothing changes: the smallest typical change's tenth, so that every place is unchanged.
    PlaceChanges still;
    for (int i = 0; i < 100; ++i) addChange({0.4, 0.4, 0.4}, everythingVisible(), still);
    EXPECT_NEAR(unchangedFitOf(still, 3).below, 1e-4, 1e-12);
    EXPECT_EQ(unchangedFitOf(still, 3).tie, 0.0);  // no noise: only exact ties
}

TEST(UnchangedThreshold, InvisiblePlacesTakeNoPart) {
    Stf visibleAbove;
    visibleAbove.curve.opacity = {{0.0, 0.0}, {0.5, 0.0}, {0.6, 1.0}};
    PlaceChanges places;
    addChange({0.1, 0.2, 0.1, 0.2, 0.1, 0.2}, visibleAbove, places);
    EXPECT_TRUE(places.changes.empty());
    addChange({0.1, 0.7, 0.1, 0.2, 0.1, 0.2}, visibleAbove, places);
    EXPECT_EQ(places.changes.size(), 1u);
    // Visible once in six: a change, but its noise is the transparent background's, not the data's.
    EXPECT_TRUE(places.noises.empty());
    addChange({0.7, 0.8, 0.7, 0.2, 0.1, 0.2}, visibleAbove, places);
    EXPECT_EQ(places.noises.size(), 1u);
}

}  // namespace
}  // namespace tstyles
