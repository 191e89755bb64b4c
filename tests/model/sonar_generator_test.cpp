// The synthetic sonar generator's pieces (tools/sonar, docs/sonar-dataset.md): the vessel's pose,
// the school's envelope, the masks, the seabed, determinism and the written series.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "sonar/fish_school.h"
#include "sonar/ping_echoes.h"
#include "sonar/seabed.h"
#include "sonar/sonar_random.h"
#include "sonar/sonar_series.h"
#include "sonar/vessel_track.h"
#include "tstyles/data/beam_geometry.h"
#include "tstyles/data/manifest.h"

namespace {

using namespace sonar;

// A cheaper survey for tests: the real beams and school, fewer range samples.
SonarSeriesOptions smallSurvey(int pings) {
    SonarSeriesOptions options;
    options.pings = pings;
    options.dims = {25, 20, 300};
    return options;
}

std::size_t count(const std::vector<std::uint8_t>& mask) {
    return std::size_t(std::count_if(mask.begin(), mask.end(), [](std::uint8_t v) { return v != 0; }));
}

std::uint16_t valueAt(const tstyles::RawTimeStep& step, std::size_t index) {
    return std::uint16_t(step.bytes[2 * index] | (step.bytes[2 * index + 1] << 8));
}

TEST(SonarRandom, SameSeedSameDrawsAndUniformsStayInsideTheOpenInterval) {
    SonarRandom a(7), b(7), c(8);
    bool anyDifferent = false;
    for (int i = 0; i < 1000; ++i) {
        const double u = a.uniform();
        EXPECT_EQ(u, b.uniform());
        EXPECT_GT(u, 0.0);
        EXPECT_LT(u, 1.0);
        anyDifferent = anyDifferent || u != c.uniform();
    }
    EXPECT_TRUE(anyDifferent);
}

TEST(SonarRandom, SpeckleHasMeanOne) {
    SonarRandom random(3);
    double sum = 0.0;
    const int draws = 200000;
    for (int i = 0; i < draws; ++i) sum += random.speckle(3);
    // The mean of 200000 gamma(3, 1/3) draws has a standard error of 0.0013.
    EXPECT_NEAR(sum / draws, 1.0, 0.01);
}

TEST(SonarRandom, PingSeedsDifferByPingAndPurpose) {
    EXPECT_NE(pingSeed(1, 0, 1), pingSeed(1, 1, 1));
    EXPECT_NE(pingSeed(1, 0, 1), pingSeed(1, 0, 2));
    EXPECT_EQ(pingSeed(1, 4, 3), pingSeed(1, 4, 3));
}

TEST(VesselTrack, TransducerLooksDownAndMovesSixMetresPerPing) {
    const VesselTrack track;
    for (int ping = 0; ping < 10; ++ping) {
        const tstyles::Placement pose = transducerPose(track, pingTime(track, ping));
        const glm::dvec3 axis = pose.rotation * glm::dvec3(0.0, 0.0, 1.0);
        // Roll 3 and pitch 1.5 degrees at most: the beams' axis stays within 4 degrees of down.
        EXPECT_GT(-axis.y, std::cos(glm::radians(4.0))) << "ping " << ping;
        EXPECT_NEAR(glm::length(pose.rotation), 1.0, 1e-12);
        EXPECT_DOUBLE_EQ(pose.origin.x, 6.0 * ping);
        EXPECT_DOUBLE_EQ(pose.origin.y, -3.0);
    }
}

TEST(FishSchool, NormalisedFrameIsTheInverseOfTheWorldMapping) {
    const SchoolShape shape = schoolShapeAt(7.3);
    for (const glm::dvec3 normalised : {glm::dvec3(0.0), glm::dvec3(0.5, -0.2, 0.7), glm::dvec3(-0.9, 0.3, 0.1)}) {
        const glm::dvec3 back = shape.toNormalised(shape.toWorld(normalised));
        EXPECT_NEAR(glm::length(back - normalised), 0.0, 1e-12);
    }
    EXPECT_NEAR(shape.normalisedRadius(shape.centre + glm::dvec3(0.0, -shape.bend / 3.0 * shape.semiAxes.y, 0.0)),
                0.0, 1e-12);
}

TEST(FishSchool, FishThinTowardTheEdge) {
    // Drawn with density (1 - r^2)^1.5: the inner half of the radius (1/8 of the volume) holds
    // I(0.5)/I(1) of the fish, where I(x) = integral of r^2 (1 - r^2)^1.5 from 0 to x: exactly
    // 1/3, far above the 1/8 a uniform cloud would give. The binomial standard error of 20000
    // fish is 0.0033; the tolerance is 4.5 of them.
    const auto fish = drawSchool(20000, 11);
    ASSERT_EQ(fish.size(), 20000u);
    std::size_t inner = 0;
    for (const Fish& one : fish) {
        EXPECT_LT(glm::length(one.home), 1.0);
        if (glm::length(one.home) < 0.5) ++inner;
    }
    EXPECT_NEAR(double(inner) / 20000.0, 1.0 / 3.0, 0.015);
}

TEST(FishSchool, DriftsAndChangesShapeBetweenPings) {
    const SchoolShape first = schoolShapeAt(0.0);
    const SchoolShape last = schoolShapeAt(18.0);
    EXPECT_GT(glm::length(last.centre - first.centre), 30.0);
    EXPECT_GT(glm::length(last.semiAxes / first.semiAxes - glm::dvec3(1.0)), 0.1);
}

TEST(Seabed, EchoPeaksAtTheFloorAndWidensForObliqueBeams) {
    const double depth = seabedDepth(10.0, 5.0);
    const glm::dvec3 down(0.0, -1.0, 0.0);
    const glm::dvec3 oblique = glm::normalize(glm::dvec3(0.0, -1.0, 0.6));
    const double onFloor = seabedEcho({10.0, -depth, 5.0}, down, depth, 0.04);
    EXPECT_GT(onFloor, seabedEcho({10.0, -depth + 1.0, 5.0}, down, depth, 0.04));
    EXPECT_GT(onFloor, seabedEcho({10.0, -depth - 1.0, 5.0}, down, depth, 0.04));
    EXPECT_LT(seabedEcho({10.0, -depth + 3.0, 5.0}, down, depth, 0.04), 1e-6);
    // 31 degrees off vertical at 88 m: the footprint spreads the peak to a sigma of 1.1 m.
    EXPECT_GT(seabedEcho({10.0, -depth + 3.0, 5.0}, oblique, depth, 0.04), 0.03);
}

TEST(PingEchoes, ValuesAreAmplitudesOfTheFullScale) {
    EXPECT_EQ(intensityToValue(0.0), 0);
    EXPECT_EQ(intensityToValue(kFullScale), 65535);
    EXPECT_EQ(intensityToValue(4.0 * kFullScale), 65535);
    EXPECT_EQ(intensityToValue(0.25 * kFullScale), std::lround(0.5 * 65535.0));
}

class SmallSurvey : public ::testing::Test {
protected:
    static void SetUpTestSuite() { series_ = new tstyles::RawSeries(buildSonarSeries(smallSurvey(3))); }
    static void TearDownTestSuite() { delete series_; }
    static const tstyles::RawSeries& series() { return *series_; }

private:
    static tstyles::RawSeries* series_;
};
tstyles::RawSeries* SmallSurvey::series_ = nullptr;

TEST_F(SmallSurvey, EveryPingIsABeamGridWithAMaskOfTheSchoolInsideTheFan) {
    ASSERT_EQ(series().steps.size(), 3u);
    for (std::size_t ping = 0; ping < 3; ++ping) {
        const tstyles::RawTimeStep& step = series().steps[ping];
        ASSERT_TRUE(step.beamGrid);
        const tstyles::BeamGrid& grid = *step.beamGrid;
        EXPECT_EQ(grid.dims, glm::ivec3(25, 20, 300));
        ASSERT_TRUE(step.mask);
        const std::size_t inside = count(*step.mask);
        // The school is a few hundred to a few thousand cubic metres in a fan of about 400000.
        EXPECT_GT(inside, 100u) << "ping " << ping;
        EXPECT_LT(inside, step.mask->size() / 20) << "ping " << ping;

        // Every masked sample is within the school's envelope (radius <= 1.1) at that ping's
        // time, and the envelope's centre is in the fan.
        const SchoolShape shape = schoolShapeAt(step.time);
        const auto centreVoxel = tstyles::beamVoxel(grid, glm::conjugate(step.placement.rotation) *
                                                             (shape.centre - step.placement.origin));
        EXPECT_TRUE(centreVoxel.has_value()) << "ping " << ping;
        double masked = 0.0, unmasked = 0.0;
        std::size_t unmaskedCount = 0;
        for (int k = 0; k < grid.dims.z; ++k)
            for (int j = 0; j < grid.dims.y; ++j)
                for (int i = 0; i < grid.dims.x; ++i) {
                    const std::size_t index = std::size_t(i + 25 * (j + 20 * k));
                    const glm::dvec3 world =
                        step.placement.origin + step.placement.rotation * tstyles::beamSamplePosition(grid, i, j, k);
                    const bool inMask = (*step.mask)[index] != 0;
                    EXPECT_EQ(inMask, shape.normalisedRadius(world) <= kMaskRadius);
                    // Compare the water column at the school's depth only (no seabed).
                    if (std::abs(world.y - shape.centre.y) > 10.0) continue;
                    if (inMask) masked += valueAt(step, index);
                    else { unmasked += valueAt(step, index); ++unmaskedCount; }
                }
        // The school echoes far above the water around it.
        EXPECT_GT(masked / double(inside), 5.0 * unmasked / double(unmaskedCount)) << "ping " << ping;
    }
}

TEST_F(SmallSurvey, ConsecutiveFansOverlapOnlyPartly) {
    // The transducers are 6 m apart and the fans 33 m long (along the track, +-16.4 m) at 45 m
    // down: a point 25 m ahead of ping 0 is outside fan 0 but inside fan 2 (13 m ahead of it);
    // a point 9 m ahead lies in fans 0 and 1 both.
    const auto& steps = series().steps;
    const auto inFan = [&](std::size_t ping, const glm::dvec3& world) {
        const tstyles::RawTimeStep& step = steps[ping];
        return tstyles::beamVoxel(*step.beamGrid, glm::conjugate(step.placement.rotation) *
                                                      (world - step.placement.origin))
            .has_value();
    };
    const glm::dvec3 ahead(25.0, -45.0, 0.0);   // 25 m along the track, 42 m below the transducers
    EXPECT_FALSE(inFan(0, ahead));
    EXPECT_TRUE(inFan(2, ahead));
    const glm::dvec3 between(9.0, -45.0, 0.0);
    EXPECT_TRUE(inFan(0, between));
    EXPECT_TRUE(inFan(1, between));
}

TEST_F(SmallSurvey, SameBytesEveryRunAndPingsIndependentOfTheirCount) {
    const tstyles::RawSeries again = buildSonarSeries(smallSurvey(2));
    ASSERT_EQ(again.steps.size(), 2u);
    for (std::size_t ping = 0; ping < 2; ++ping) {
        EXPECT_EQ(again.steps[ping].bytes, series().steps[ping].bytes) << "ping " << ping;
        EXPECT_EQ(again.steps[ping].mask, series().steps[ping].mask) << "ping " << ping;
        EXPECT_EQ(again.steps[ping].placement, series().steps[ping].placement);
    }
    EXPECT_NE(series().steps[0].bytes, series().steps[1].bytes);
}

TEST_F(SmallSurvey, WrittenSeriesLoadsBackWithBeamGridsAndMasks) {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("tstyles-sonar-test-" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
    tstyles::writeSeries(series(), folder);
    const tstyles::Series loaded = tstyles::loadSeries(folder);
    ASSERT_EQ(loaded.size(), 3u);
    for (std::size_t ping = 0; ping < 3; ++ping) {
        const tstyles::TimeStep& step = loaded.steps[ping];
        ASSERT_TRUE(step.isBeam());
        EXPECT_EQ(step.beam(), *series().steps[ping].beamGrid);
        EXPECT_EQ(step.sourceType, tstyles::ValueType::UInt16);
        ASSERT_TRUE(step.mask);
        EXPECT_EQ(count(*step.mask), count(*series().steps[ping].mask));
        EXPECT_NEAR(step.density[1234], valueAt(series().steps[ping], 1234) / 65535.0, 1e-6);
    }
    std::filesystem::remove_all(folder);
}

}  // namespace
