// The program variant's switches that the renderer derives from the series and the scene: the
// empty-brick test's threshold, and the styled tracks.
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "tstyles/render/raycast_variant.h"

namespace tstyles::testing {
namespace {

std::map<std::string, std::string> definesOf(const RaycastVariant& variant) {
    std::map<std::string, std::string> defines;
    for (const auto& [name, value] : variant.defines()) defines[name] = value;
    return defines;
}

// Whether it pays is measured by `tstyles bench` (docs/performance.md); here, the rule that follows
// from that measurement: compiled in from 5 % of the bricks empty, and the define it sets.
TEST(RaycastVariant, TheEmptyBrickTestIsCompiledInFromFivePercentEmptyBricks) {
    EXPECT_EQ(kMinEmptyBrickShare, 0.05);
    EXPECT_FALSE(skipsEmptyBricks(0.0));
    EXPECT_FALSE(skipsEmptyBricks(std::nextafter(kMinEmptyBrickShare, 0.0)));
    EXPECT_TRUE(skipsEmptyBricks(kMinEmptyBrickShare));
    EXPECT_TRUE(skipsEmptyBricks(0.9));
    RaycastVariant variant;
    variant.skipEmptyBricks = false;
    EXPECT_EQ(definesOf(variant)["SKIP_EMPTY_BRICKS"], "0");
    variant.skipEmptyBricks = true;
    EXPECT_EQ(definesOf(variant)["SKIP_EMPTY_BRICKS"], "1");
}

TEST(RaycastVariant, StyledTracksAreABitPerTrackAndStyledIsAnyOfThem) {
    RaycastVariant variant;
    EXPECT_FALSE(variant.styled());
    EXPECT_EQ(definesOf(variant)["STYLED"], "0");
    EXPECT_EQ(definesOf(variant)["STYLED_TRACKS"], "0");
    variant.styledTracks = 1 << 1;  // the index TSTF alone
    EXPECT_TRUE(variant.styled());
    EXPECT_EQ(definesOf(variant)["STYLED"], "1");
    EXPECT_EQ(definesOf(variant)["STYLED_TRACKS"], "2");
}

TEST(RaycastVariant, BeamAndMissingValueSwitchesFollowTheSeries) {
    RaycastVariant variant;
    variant.beamGrids = true;
    variant.evenBeams = true;
    variant.missingValues = true;
    const auto defines = definesOf(variant);
    EXPECT_EQ(defines.at("BEAM_GRIDS"), "1");
    EXPECT_EQ(defines.at("EVEN_BEAMS"), "1");
    EXPECT_EQ(defines.at("MISSING_VALUES"), "1");
    // A rectilinear grid beside the beams keeps the test of each time-step's kind in the program.
    EXPECT_EQ(defines.at("RECTILINEAR_GRIDS"), "1");
    variant.rectilinearGrids = false;
    EXPECT_EQ(definesOf(variant).at("RECTILINEAR_GRIDS"), "0");
    // Different switches are different programs in the cache.
    RaycastVariant uneven = variant;
    uneven.evenBeams = false;
    EXPECT_NE(variant, uneven);
}

}  // namespace
}  // namespace tstyles::testing
