// The reader options' table (tstyles/data/reader_option_table.h): each line sets its field of
// ReadOptions from its text and says it was given; values outside a line's bounds or choices are
// refused with the bounds in words; the format rows name only the table's format-only options, and
// every such option is some format's; the opener refuses from the table what a manifest or a format
// does not take.
#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "readers/format_table.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/reader_option_table.h"
#include "tstyles/data/series_opener.h"

namespace tstyles {
namespace {

// The message of the InputError that reading `texts` throws, or "" where none is thrown.
std::string refusal(const ReaderOptionTexts& texts) {
    try {
        readOptionsFrom(texts);
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(ReaderOptionTable, EachLineSetsItsFieldAndSaysItWasGiven) {
    const ReaderOptionTexts texts = {
        {"var", {"temperature"}},   {"time-dim", {"t"}},         {"index-axes", {"true"}},
        {"steps", {"2:8:3"}},       {"range", {"-5:40"}},        {"resample", {"64x32x16"}},
        {"dims", {"500x500x100"}},  {"channel", {"2"}},          {"series", {"3"}},
        {"axes", {"ZTYX"}},         {"level", {"1"}},            {"precision", {"8"}},
        {"max-memory", {"2G"}},     {"fit", {"resolution"}},     {"solution", {"a.q", "b.q"}},
        {"block", {"4"}},           {"gamma", {"1.3"}}};
    const ReadOptions options = readOptionsFrom(texts);
    EXPECT_EQ(options.variable, "temperature");
    EXPECT_EQ(options.timeDimension, "t");
    EXPECT_TRUE(options.indexAxes);
    ASSERT_TRUE(options.steps);
    EXPECT_EQ(options.steps->first, 2u);
    EXPECT_EQ(options.steps->end, std::optional<std::size_t>(8));
    EXPECT_EQ(options.steps->stride, 3u);
    EXPECT_EQ(options.valueRange, (std::optional<std::array<double, 2>>{{-5.0, 40.0}}));
    EXPECT_EQ(options.resampleTo, std::optional<glm::ivec3>(glm::ivec3(64, 32, 16)));
    EXPECT_EQ(options.rawDims, std::optional<glm::ivec3>(glm::ivec3(500, 500, 100)));
    EXPECT_EQ(options.channel, std::optional<int>(2));
    EXPECT_EQ(options.seriesChoice, "3");
    EXPECT_EQ(options.pageAxes, "ZTYX");
    EXPECT_EQ(options.level, std::optional<int>(1));
    EXPECT_EQ(options.precision, DensityPrecision::Bits8);
    EXPECT_EQ(options.maxMemoryBytes, std::optional<std::uint64_t>(2ull << 30));
    EXPECT_EQ(options.fit, MemoryFit::Resolution);
    EXPECT_EQ(options.solutionFiles, (std::vector<std::filesystem::path>{"a.q", "b.q"}));
    EXPECT_EQ(options.block, 4);
    EXPECT_DOUBLE_EQ(options.gamma, 1.3);
    // Every line of the table was given above, and each says so.
    EXPECT_EQ(readerOptionsGiven(options).size(), readerOptionLines().size());
    EXPECT_EQ(texts.size(), readerOptionLines().size());
    EXPECT_TRUE(readerOptionsGiven(readOptionsFrom({})).empty()) << "the defaults read as given";
}

TEST(ReaderOptionTable, ValuesOutsideTheBoundsAreRefusedWithTheBoundsInWords) {
    EXPECT_EQ(refusal({{"level", {"-1"}}}), "--level: must be a whole number 0 or more; got \"-1\"");
    EXPECT_EQ(refusal({{"channel", {"1.5"}}}), "--channel: must be a whole number 0 or more; got \"1.5\"");
    EXPECT_EQ(refusal({{"block", {"99999999999"}}}), "--block: must be a whole number 0 or more; got \"99999999999\"");
    EXPECT_EQ(refusal({{"gamma", {"1"}}}), "--gamma: must be a number above 1 and at most 10; got \"1\"");
    EXPECT_EQ(refusal({{"gamma", {"nan"}}}), "--gamma: must be a number above 1 and at most 10; got \"nan\"");
    EXPECT_EQ(refusal({{"precision", {"12"}}}), "--precision: must be 8, 16 or 32; got \"12\"");
    EXPECT_EQ(refusal({{"fit", {"crop"}}}), "--fit: must be refuse, resolution or steps; got \"crop\"");
    EXPECT_EQ(refusal({{"fit", {"steps"}}}), "--fit: says what to do over --max-memory, which is not given");
    EXPECT_EQ(refusal({{"levels", {"1"}}}), "levels: is not a reader option");
    EXPECT_EQ(refusal({{"level", {"0"}}}), "");
    EXPECT_EQ(refusal({{"gamma", {"10"}}}), "");
}

TEST(ReaderOptionTable, TheFormatRowsSayWhichOptionsAreFormatOnly) {
    for (const SeriesFormat& format : seriesFormats())
        for (const std::string& option : format.options) {
            const ReaderOptionLine* line = readerOptionNamed(option);
            ASSERT_NE(line, nullptr) << format.name << " names " << option << ", which the table lacks";
            EXPECT_EQ(line->cli, option) << format.name << " names an option by other than its spelling";
        }
    // What the rows make format-only: the options of one reader or a few; the rest every reader takes.
    const std::set<std::string_view> formatOnly{"--var",   "--time-dim", "--index-axes", "--dims",
                                                "--channel", "--series", "--axes",       "--level",
                                                "--solution", "--block", "--gamma"};
    for (const ReaderOptionLine& line : readerOptionLines())
        EXPECT_EQ(isFormatOnly(line), formatOnly.count(line.cli) == 1) << line.cli;
}

TEST(ReaderOptionTable, KeysSpellingsAndKeywordsAreUnique) {
    std::set<std::string_view> seen;
    for (const ReaderOptionLine& line : readerOptionLines()) {
        EXPECT_TRUE(seen.insert(line.cli).second) << line.cli;
        EXPECT_EQ(readerOptionNamed(line.key), &line);
        EXPECT_EQ(readerOptionNamed(line.python), &line);
        EXPECT_EQ("--" + std::string(line.key), line.cli);
    }
}

TEST(ReaderOptionTable, TheOpenerRefusesFromTheTable) {
    const std::filesystem::path manifest = std::filesystem::path(TSTYLES_SOURCE_DIR) / "data" / "hurricane";
    ReadOptions options;
    options.level = 1;
    try {
        openSeries(manifest, options);
        FAIL() << "a manifest took --level";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("--level: applies to the files a reader reads (OME-Zarr, TIFF), not to a "
                                                 "tstyles manifest"),
                  std::string::npos)
            << error.what();
    }
    // What a manifest takes: the precision and the memory limit.
    for (const ReaderOptionLine& line : readerOptionLines())
        EXPECT_EQ(line.forManifest, line.key == "precision" || line.key == "max-memory") << line.cli;
}

}  // namespace
}  // namespace tstyles
