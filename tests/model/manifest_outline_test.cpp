// Reading a manifest without its values (loadSeriesOutline), and the hook that sees each time-step
// as it is read (ManifestLimits::nodesToRead and afterStepRead), which distributed rendering reads
// blocks with.
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_dataset.h"
#include "tstyles/data/manifest.h"

namespace {

using nlohmann::json;
using tstyles_test::baseManifest;
using tstyles_test::expectMentions;
using tstyles_test::writeBaseDataset;

TEST(ManifestOutline, ReadsNoValueFile) {
    const auto folder = writeBaseDataset("outline", baseManifest());
    std::filesystem::remove(folder / "t00.raw");
    std::filesystem::remove(folder / "t01.raw");
    std::filesystem::remove(folder / "t00_mask.raw");
    const tstyles::Series outline = tstyles::loadSeriesOutline(folder / "series.json");
    ASSERT_EQ(outline.size(), 2u);
    EXPECT_EQ(outline.steps[1].time, 1.0);
    EXPECT_EQ(outline.steps[0].dims(), glm::ivec3(2, 3, 4));
    EXPECT_EQ(outline.steps[0].placement.origin, glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_TRUE(outline.steps[0].density.empty());
    EXPECT_EQ(outline.valueRange[0], 0.0);  // the manifest's value_range
    EXPECT_EQ(outline.valueRange[1], 255.0);
    EXPECT_EQ(outline.name, "base");
}

TEST(ManifestOutline, AValueRangeFromTheDataIsUnknown) {
    json manifest = baseManifest();
    manifest.erase("value_range");
    const tstyles::Series outline = tstyles::loadSeriesOutline(writeBaseDataset("outline_no_range", manifest) / "series.json");
    EXPECT_TRUE(std::isnan(outline.valueRange[0]));
    EXPECT_TRUE(std::isnan(outline.valueRange[1]));
}

TEST(ManifestOutline, ChecksTheManifestAsLoadSeriesDoes) {
    json manifest = baseManifest();
    manifest["time_steps"][1]["time"] = 0.0;
    const auto folder = writeBaseDataset("outline_bad_times", manifest);
    try {
        tstyles::loadSeriesOutline(folder / "series.json");
        FAIL() << "times out of order were accepted";
    } catch (const tstyles::InputError& error) {
        expectMentions(error.what(), {"time_steps[1].time", "strictly increasing"});
    }
}

// Where only a block of each time-step is kept, the reader asks for the nodes before it opens the
// files, keeps those values and mask bytes alone (x fastest) and hands the time-step raw to the
// hook; the range still comes from every value of the whole files.
TEST(ManifestBlockReading, KeepsTheBlocksNodesAndTheWholeFilesRange) {
    json manifest = baseManifest();
    manifest.erase("value_range");
    const auto folder = writeBaseDataset("block_reading", manifest);
    tstyles_test::writeBytes(folder / "t00_mask.raw", tstyles_test::rampBytes(tstyles_test::kBaseVoxels));
    // Nodes x = 1, y = 1..2, z = 2..3 of the 2 x 3 x 4 ramp (value = x + 2 y + 6 z).
    const tstyles::NodeBlock block{{1, 1, 2}, {1, 2, 2}};
    const std::vector<float> blockValues{15.0f, 17.0f, 21.0f, 23.0f};
    std::vector<std::size_t> asked;
    std::vector<std::size_t> seen;
    tstyles::ManifestLimits limits;
    limits.nodesToRead = [&](std::size_t index, const tstyles::TimeStep& outline) {
        asked.push_back(index);
        EXPECT_TRUE(outline.density.empty());  // asked before the values are read
        EXPECT_EQ(outline.dims(), glm::ivec3(2, 3, 4));
        return std::optional<tstyles::NodeBlock>(block);
    };
    limits.afterStepRead = [&](std::size_t index, tstyles::TimeStep& step) {
        seen.push_back(index);
        EXPECT_EQ(step.density, blockValues);  // raw, before the range maps it to density
        if (index == 0) {
            EXPECT_EQ(*step.mask, (std::vector<std::uint8_t>{15, 17, 21, 23}));
        }
    };
    limits.keptVoxels = 8;
    const tstyles::Series series = tstyles::loadSeries(folder / "series.json", limits);
    EXPECT_EQ(asked, (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1}));
    // From the whole files: 0 and 23 are outside the block but for 23.
    EXPECT_EQ(series.valueRange[0], 0.0);
    EXPECT_EQ(series.valueRange[1], 23.0);
    ASSERT_EQ(series.steps[1].density.size(), 4u);
    EXPECT_FLOAT_EQ(series.steps[1].density[0], 15.0f / 23.0f);
}

// Without "value_range" a bad value outside the block is still found: the whole file is read
// through for the range. (With it, only the block's rows are read, and the process whose block
// holds the value finds it: SeriesCrop.AGivenValueRangeReadsOnlyTheBlocksRows.)
TEST(ManifestBlockReading, WithoutAValueRangeABadValueOutsideTheBlockIsStillAnError) {
    json manifest = baseManifest();
    manifest.erase("value_range");
    manifest["time_steps"][1]["values"]["type"] = "float32";
    const auto folder = writeBaseDataset("block_reading_inf", manifest);
    std::vector<float> values(tstyles_test::kBaseVoxels, 1.0f);
    values[0] = -std::numeric_limits<float>::infinity();  // node (0, 0, 0), outside the block
    std::vector<std::uint8_t> bytes(values.size() * sizeof(float));
    std::memcpy(bytes.data(), values.data(), bytes.size());
    tstyles_test::writeBytes(folder / "t01.raw", bytes);
    tstyles::ManifestLimits limits;
    limits.nodesToRead = [](std::size_t, const tstyles::TimeStep&) {
        return std::optional<tstyles::NodeBlock>(tstyles::NodeBlock{{1, 1, 2}, {1, 2, 2}});
    };
    limits.afterStepRead = [](std::size_t, tstyles::TimeStep&) {};
    limits.keptVoxels = 8;
    try {
        tstyles::loadSeries(folder / "series.json", limits);
        FAIL() << "an infinity outside the block was accepted";
    } catch (const tstyles::InputError& error) {
        expectMentions(error.what(), {"t01.raw", "-Inf", "(0, 0, 0)"});
    }
}

// Reading a block, the memory check counts the voxels kept, not the series.
TEST(ManifestBlockReading, TheMemoryCheckCountsTheKeptVoxels) {
    const auto folder = writeBaseDataset("block_reading_memory", baseManifest());
    tstyles::ManifestLimits limits;
    // The whole series: 2 x 24 voxels at 4 + 2 bytes and 24 mask bytes, 312 bytes.
    limits.maxMemoryBytes = 200;
    EXPECT_THROW(tstyles::loadSeries(folder / "series.json", limits), tstyles::InputError);
    limits.nodesToRead = [](std::size_t, const tstyles::TimeStep&) {
        return std::optional<tstyles::NodeBlock>(tstyles::NodeBlock{{0, 0, 0}, {2, 3, 2}});
    };
    limits.afterStepRead = [](std::size_t, tstyles::TimeStep&) {};
    limits.keptVoxels = 24;  // 24 x 7 bytes: 168 bytes
    EXPECT_NO_THROW(tstyles::loadSeries(folder / "series.json", limits));
    limits.keptVoxels = 30;  // 210 bytes
    try {
        tstyles::loadSeries(folder / "series.json", limits);
        FAIL() << "over the cap";
    } catch (const tstyles::InputError& error) {
        expectMentions(error.what(), {"time_steps", "the 30 voxels kept"});
    }
}

}  // namespace
