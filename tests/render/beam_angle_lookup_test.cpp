// The loop-free beam angle lookup (render/beam_angle_table.h, mirrored by fractionalBeamIndex in
// shaders/beam_grid.glsl) gives the data model's fractional beam index (data/beam_geometry.h) on
// the sonar survey's even fans and on uneven beam lists, and refuses angles too uneven for it.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/data/beam_geometry.h"
#include "tstyles/render/beam_angle_table.h"

namespace tstyles {
namespace {

// Every angle from a bit before the first beam to a bit after the last, and every beam exactly.
void expectLookupMatchesBeamGeometry(const std::vector<double>& anglesDeg) {
    std::vector<float> table{0.5f, 0.25f};  // something before the run, as other time-steps' runs
    const int first = appendBeamAngleRun(anglesDeg, table, "series.json", "time_steps[0].grid.azimuth_deg");
    ASSERT_EQ(first, 2);
    const int count = int(anglesDeg.size());
    std::vector<double> probes = anglesDeg;
    const double span = anglesDeg.back() - anglesDeg.front();
    for (int i = -200; i <= 20200; ++i) probes.push_back(anglesDeg.front() + span * i / 20000.0);
    int inside = 0;
    for (const double angleDeg : probes) {
        // The angle as the shader gets it: float radians.
        const float angleRad = float(glm::radians(angleDeg));
        const double storedDeg = glm::degrees(double(angleRad));
        const std::optional<double> expected = fractionalBeamIndex(anglesDeg, storedDeg);
        const float found = lookUpBeamIndex(table, first, count, angleRad);
        // Within float rounding of the first and last beam the two may disagree on inside/outside.
        const double edge = 1e-5;
        if (storedDeg > anglesDeg.front() + edge && storedDeg < anglesDeg.back() - edge) {
            ASSERT_TRUE(expected.has_value()) << "at " << angleDeg;
            // Float radians: about 1e-7 of the angle, over a gap of a fraction of a degree.
            EXPECT_NEAR(found, *expected, 1e-4) << "at " << angleDeg << " degrees";
            ++inside;
        } else if (storedDeg < anglesDeg.front() - edge || storedDeg > anglesDeg.back() + edge) {
            EXPECT_EQ(found, -1.0f) << "at " << angleDeg << " degrees, outside the fan";
        }
    }
    EXPECT_GT(inside, 19000);
}

TEST(BeamAngleLookup, SonarSurveyFans) {
    // data/sonar: 25 beams across over +-30 degrees, 20 along over +-20 degrees.
    expectLookupMatchesBeamGeometry(evenBeamAngles(-30.0, 30.0, 25));
    expectLookupMatchesBeamGeometry(evenBeamAngles(-20.0, 20.0, 20));
}

TEST(BeamAngleLookup, ManyBeamsAndTwoBeams) {
    expectLookupMatchesBeamGeometry(evenBeamAngles(-65.0, 65.0, 512));
    expectLookupMatchesBeamGeometry({-10.0, 10.0});
}

TEST(BeamAngleLookup, UnevenBeams) {
    // Beams bunched near the axis, as equi-distant beam forming gives: gaps from 0.05 to 4 degrees.
    std::vector<double> angles;
    for (int i = -30; i <= 30; ++i) angles.push_back(60.0 * std::sin(glm::radians(1.5 * i)));
    expectLookupMatchesBeamGeometry(angles);
    expectLookupMatchesBeamGeometry({-40.0, -39.9, -12.0, 0.0, 0.05, 33.0, 70.0});
}

TEST(BeamAngleLookup, RefusesBeamsTooCloseForTheLookupNamingTheField) {
    std::vector<float> table;
    try {
        appendBeamAngleRun({-40.0, 0.0, 0.0001, 40.0}, table, "survey/series.json",
                           "time_steps[3].grid.azimuth_angles_deg");
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("survey/series.json"), std::string::npos) << message;
        EXPECT_NE(message.find("time_steps[3].grid.azimuth_angles_deg"), std::string::npos) << message;
        EXPECT_NE(message.find("too close together"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace tstyles
