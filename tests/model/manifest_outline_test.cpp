// Reading a manifest without its values (loadSeriesOutline), and the hook that sees each time-step
// as it is read (ManifestLimits::afterStepRead), which distributed rendering cuts blocks with.
#include <cmath>
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

// The hook sees every time-step in order, raw (before the value range maps it to density), and
// what it leaves is what the series holds; the range still comes from the whole time-steps.
TEST(ManifestStepHook, SeesEachTimeStepRawAndKeepsWhatItCuts) {
    json manifest = baseManifest();
    manifest.erase("value_range");
    const auto folder = writeBaseDataset("hook", manifest);
    std::vector<std::size_t> seen;
    tstyles::ManifestLimits limits;
    limits.afterStepRead = [&](std::size_t index, tstyles::TimeStep& step) {
        seen.push_back(index);
        EXPECT_EQ(step.density[23], 23.0f);  // raw: the ramp's last value
        step.density.resize(1);               // keep the first voxel only
        if (step.mask) step.mask->resize(1);
    };
    limits.keptVoxels = 2;
    const tstyles::Series series = tstyles::loadSeries(folder / "series.json", limits);
    EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(series.valueRange[1], 23.0);  // from the whole time-steps, before the cut
    ASSERT_EQ(series.steps[1].density.size(), 1u);
    EXPECT_EQ(series.steps[1].density[0], 0.0f);
}

// With a hook the memory check counts what it keeps and the largest time-step, not the series.
TEST(ManifestStepHook, TheMemoryCheckCountsTheKeptVoxels) {
    const auto folder = writeBaseDataset("hook_memory", baseManifest());
    tstyles::ManifestLimits limits;
    // The whole series: 2 x 24 voxels at 4 + 2 bytes and 24 mask bytes, 312 bytes.
    limits.maxMemoryBytes = 200;
    EXPECT_THROW(tstyles::loadSeries(folder / "series.json", limits), tstyles::InputError);
    limits.afterStepRead = [](std::size_t, tstyles::TimeStep&) {};
    limits.keptVoxels = 10;  // 10 x 7 bytes and the largest time-step's 24 x 5: 190 bytes
    EXPECT_NO_THROW(tstyles::loadSeries(folder / "series.json", limits));
    limits.keptVoxels = 20;  // 260 bytes
    try {
        tstyles::loadSeries(folder / "series.json", limits);
        FAIL() << "over the cap";
    } catch (const tstyles::InputError& error) {
        expectMentions(error.what(), {"time_steps", "the 20 voxels kept", "largest time-step"});
    }
}

}  // namespace
