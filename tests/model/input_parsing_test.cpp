// The hand-written parsers that replaced std::regex (GCC 12's <regex> warns under the sanitizers):
// each accepts what the pattern accepted and refuses what it refused. Also the stderr capture that
// keeps library messages inside our one line, and the memory cap's refusal text.
#include <gtest/gtest.h>

#include <unistd.h>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/stderr_capture.h"
#include "tstyles/data/read_options.h"
#include "tstyles/data/time_axis.h"

namespace tstyles {
namespace {

TEST(InputParsing, MemorySizes) {
    EXPECT_EQ(parseMemorySize("800000", "--max-memory"), 800000u);
    EXPECT_EQ(parseMemorySize("512M", "--max-memory"), 512u << 20);
    EXPECT_EQ(parseMemorySize("2g", "--max-memory"), 2ull << 30);
    EXPECT_EQ(parseMemorySize("1.5GiB", "--max-memory"), 3ull << 29);
    EXPECT_EQ(parseMemorySize("64 KB", "--max-memory"), 64u << 10);
    EXPECT_EQ(parseMemorySize("1T", "--max-memory"), 1ull << 40);
    for (const char* bad : {"", "M", ".5G", "5.G", "12MBx", "-1", "1 G B", "1X", "1e9", "512M "})
        EXPECT_THROW(parseMemorySize(bad, "--max-memory"), InputError) << bad;
}

TEST(InputParsing, Dims) {
    EXPECT_EQ(parseDims("125x125x25", "--dims"), glm::ivec3(125, 125, 25));
    EXPECT_EQ(parseDims("2x2x99999", "--dims"), glm::ivec3(2, 2, 99999));
    for (const char* bad : {"", "2x2", "2x2x2x2", "2x2x", "x2x2", "2X2X2", "2x2x123456", "2 x2x2", "2x2x2 ", "1x2x2"})
        EXPECT_THROW(parseDims(bad, "--dims"), InputError) << bad;
}

CalendarDate referenceOf(const std::string& units) {
    return parseTimeUnits(units, "", "f.nc", "time").reference.value();
}

TEST(InputParsing, ReferenceDates) {
    EXPECT_EQ(referenceOf("days since 1950-01-01"), (CalendarDate{1950, 1, 1, 0, 0, 0.0}));
    EXPECT_EQ(referenceOf("hours since 2000-01-01 0"), (CalendarDate{2000, 1, 1, 0, 0, 0.0}));
    EXPECT_EQ(referenceOf("hours since 2009-07-01T06:30:15.5Z"), (CalendarDate{2009, 7, 1, 6, 30, 15.5}));
    EXPECT_EQ(referenceOf("days since 1-1-1 utc"), (CalendarDate{1, 1, 1, 0, 0, 0.0}));
    EXPECT_EQ(referenceOf("days since 2000-01-01 +00:00"), (CalendarDate{2000, 1, 1, 0, 0, 0.0}));
    EXPECT_EQ(referenceOf("days since 2000-01-01 10 -0"), (CalendarDate{2000, 1, 1, 10, 0, 0.0}));
    EXPECT_EQ(referenceOf("seconds since 2000-01-01 00:00:0."), (CalendarDate{2000, 1, 1, 0, 0, 0.0}));
    EXPECT_EQ(referenceOf("days since -100-03-01").year, -100);
    for (const char* bad : {"days since 2000-01", "days since 2000-01-01 +01:00", "days since 2000-01-01 10:00 x",
                            "days since 20000-01-01", "days since 2000-001-01", "days since 2000-01-01 123",
                            "days since 2000-01-01 +", "days since 2000/01/01"})
        EXPECT_THROW(parseTimeUnits(bad, "", "f.nc", "time"), InputError) << bad;
}

TEST(InputParsing, StderrCaptureKeepsLibraryLinesOut) {
    std::string captured;
    {
        const StderrCapture capture;
        const char text[] = "libpng error: IDAT: CRC error\n** ERROR: nifti_image_read: bad header\n";
        ASSERT_EQ(::write(STDERR_FILENO, text, sizeof text - 1), ssize_t(sizeof text - 1));
        captured = capture.text();
    }
    EXPECT_EQ(captured, "IDAT: CRC error; nifti_image_read: bad header");
}

TEST(InputParsing, MemoryRefusalNamesTheFigure) {
    EXPECT_NO_THROW(requireMemory("f.raw", "", 1024.0, 1024, "the values"));
    try {
        requireMemory("f.raw", "dims", 3.0 * 1024 * 1024 * 1024, 1 << 30, "the values");
        FAIL() << "no refusal";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(),
                     "f.raw: dims: the values need 3.0 GiB, more than the 1.0 GiB of memory allowed (--max-memory; "
                     "default half of this machine's memory)");
    }
    EXPECT_GT(defaultMemoryCap(), 0u);
}

}  // namespace
}  // namespace tstyles
