// The one lower-case helper (tstyles/core/ascii_case.h): ASCII letters lowered, every other byte
// (UTF-8 "µ", digits, dots) kept.
#include <gtest/gtest.h>

#include "tstyles/core/ascii_case.h"

namespace tstyles {
namespace {

TEST(AsciiCase, LowersAsciiLettersAndKeepsOtherBytes) {
    EXPECT_EQ(asciiLowercase("Degrees_North 2"), "degrees_north 2");
    EXPECT_EQ(asciiLowercase("\xC2\xB5M"), "\xC2\xB5m");  // "µM": the UTF-8 bytes of µ stay
    EXPECT_EQ(asciiLowercase(""), "");
    EXPECT_EQ(lowercaseExtension("/data/BRAIN.NII"), ".nii");
    EXPECT_EQ(lowercaseExtension("scan.nii.GZ"), ".gz");
    EXPECT_EQ(lowercaseExtension("README"), "");
    EXPECT_EQ(lowercaseFileName("/a/b/Series.JSON"), "series.json");
}

}  // namespace
}  // namespace tstyles
