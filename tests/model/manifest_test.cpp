// Good manifests load with the right numbers, and writeSeries round-trips through loadSeries.
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "test_dataset.h"
#include "tstyles/data/manifest.h"

namespace {

using nlohmann::json;
using tstyles::ValueType;

// One time-step (2 x 3 x 4 voxels) whose values file `t00.raw` holds `bytes` of `type`.
std::filesystem::path singleStepDataset(const std::string& name, const std::string& type,
                                        const std::vector<std::uint8_t>& bytes, const json& valueRange) {
    json step = tstyles_test::baseStep(0.0, "t00");
    step["values"]["type"] = type;
    json manifest = {{"format", "tstyles-series"}, {"version", 1}, {"time_steps", {step}}};
    if (!valueRange.is_null()) manifest["value_range"] = valueRange;
    const auto folder = tstyles_test::freshFolder(name);
    tstyles_test::writeBytes(folder / "t00.raw", bytes);
    tstyles_test::writeText(folder / "series.json", manifest.dump(2));
    return folder / "series.json";
}

TEST(LoadSeries, Uint8IsNormalisedByTheValueRange) {
    std::vector<std::uint8_t> bytes(tstyles_test::kBaseVoxels, 51);
    bytes[0] = 0;
    bytes[23] = 255;
    const auto series = tstyles::loadSeries(singleStepDataset("uint8", "uint8", bytes, {0, 255}));
    ASSERT_EQ(series.size(), 1u);
    const auto& step = series.steps[0];
    EXPECT_EQ(step.sourceType, ValueType::UInt8);
    ASSERT_EQ(step.density.size(), tstyles_test::kBaseVoxels);
    EXPECT_EQ(step.density[0], 0.0f);
    EXPECT_EQ(step.density[1], 0.2f);  // 51 / 255 is 0.2 exactly
    EXPECT_EQ(step.density[23], 1.0f);
    EXPECT_EQ(step.rawRange[0], 0.0);
    EXPECT_EQ(step.rawRange[1], 255.0);
}

TEST(LoadSeries, Uint16IsLittleEndianAndClampedToTheRange) {
    std::vector<std::uint16_t> values(tstyles_test::kBaseVoxels, 250);
    values[0] = 0;
    values[5] = 1200;  // above the range's high end: density 1
    const auto series = tstyles::loadSeries(
        singleStepDataset("uint16", "uint16", tstyles_test::uint16Bytes(values), {0, 1000}));
    const auto& step = series.steps[0];
    EXPECT_EQ(step.sourceType, ValueType::UInt16);
    EXPECT_EQ(step.density[0], 0.0f);
    EXPECT_EQ(step.density[1], 0.25f);
    EXPECT_EQ(step.density[5], 1.0f);
    EXPECT_EQ(step.rawRange[1], 1200.0);
}

TEST(LoadSeries, Float32IsNormalisedAndClamped) {
    std::vector<float> values(tstyles_test::kBaseVoxels, 0.0f);
    values[1] = -1.0f;
    values[2] = 0.5f;
    values[3] = -3.0f;  // below the range's low end: density 0
    const auto series = tstyles::loadSeries(
        singleStepDataset("float32", "float32", tstyles_test::float32Bytes(values), {-1, 1}));
    const auto& step = series.steps[0];
    EXPECT_EQ(step.sourceType, ValueType::Float32);
    EXPECT_EQ(step.density[0], 0.5f);
    EXPECT_EQ(step.density[1], 0.0f);
    EXPECT_EQ(step.density[2], 0.75f);
    EXPECT_EQ(step.density[3], 0.0f);
    EXPECT_EQ(step.rawRange[0], -3.0);
    EXPECT_EQ(step.rawRange[1], 0.5);
}

TEST(LoadSeries, DefaultValueRangeSpansAllTimeSteps) {
    json manifest = tstyles_test::baseManifest();
    manifest.erase("value_range");
    const auto folder = tstyles_test::writeBaseDataset("default_range", manifest);
    std::vector<std::uint8_t> first(tstyles_test::kBaseVoxels, 10), second(tstyles_test::kBaseVoxels, 10);
    first[0] = 20;
    second[0] = 5;
    tstyles_test::writeBytes(folder / "t00.raw", first);
    tstyles_test::writeBytes(folder / "t01.raw", second);
    const auto series = tstyles::loadSeries(folder / "series.json");
    EXPECT_EQ(series.valueRange[0], 5.0);
    EXPECT_EQ(series.valueRange[1], 20.0);
    EXPECT_FLOAT_EQ(series.steps[0].density[1], 1.0f / 3.0f);
    EXPECT_EQ(series.steps[0].density[0], 1.0f);
    EXPECT_EQ(series.steps[1].density[0], 0.0f);
    EXPECT_EQ(series.steps[0].rawRange[0], 10.0);
    EXPECT_EQ(series.steps[1].rawRange[1], 10.0);
}

TEST(LoadSeries, ReadsGridPlacementMaskAndPaths) {
    const auto folder = tstyles_test::writeBaseDataset("fields", tstyles_test::baseManifest());
    const auto series = tstyles::loadSeries(folder / "series.json");
    EXPECT_EQ(series.name, "base");
    EXPECT_EQ(series.manifestPath, folder / "series.json");
    ASSERT_EQ(series.size(), 2u);
    const auto& step = series.steps[0];
    EXPECT_EQ(series.steps[1].time, 1.0);
    EXPECT_EQ(step.rectilinear().dims, glm::ivec3(2, 3, 4));
    EXPECT_EQ(step.rectilinear().spacing, glm::dvec3(0.5, 0.5, 0.25));
    EXPECT_EQ(step.placement.origin, glm::dvec3(1.0, 2.0, 3.0));
    const glm::dquat expected = glm::angleAxis(glm::radians(30.0), glm::dvec3(0, 0, 1));
    EXPECT_NEAR(glm::dot(step.placement.rotation, expected), 1.0, 1e-12);
    EXPECT_EQ(step.valuesFile, folder / "t00.raw");
    EXPECT_EQ(step.maskFile, folder / "t00_mask.raw");
    ASSERT_TRUE(step.mask.has_value());
    EXPECT_EQ(*step.mask, std::vector<std::uint8_t>(tstyles_test::kBaseVoxels, 1));
    EXPECT_FALSE(series.steps[1].mask.has_value());
    EXPECT_TRUE(series.hasMasks());
}

TEST(LoadSeries, OptionalKeysHaveDefaults) {
    json manifest = tstyles_test::baseManifest();
    manifest.erase("name");
    manifest["time_steps"][0].erase("placement");
    manifest["time_steps"][1]["placement"].erase("rotation");
    const auto folder = tstyles_test::writeBaseDataset("defaults", manifest);
    // Named by its folder, the dataset's manifest is series.json.
    const auto series = tstyles::loadSeries(folder);
    EXPECT_EQ(series.name, folder.filename().string());
    EXPECT_EQ(series.steps[0].placement, tstyles::Placement{});
    EXPECT_EQ(series.steps[1].placement.origin, glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_EQ(series.steps[1].placement.rotation, glm::dquat(1.0, 0.0, 0.0, 0.0));
}

TEST(LoadSeries, RotationAxisIsNormalised) {
    json manifest = tstyles_test::baseManifest();
    manifest["time_steps"][0]["placement"]["rotation"] = {{"axis", {0, 0, 5}}, {"angle_deg", 90.0}};
    const auto series = tstyles::loadSeries(tstyles_test::writeBaseDataset("axis", manifest) / "series.json");
    const glm::dvec4 world = series.steps[0].placement.gridToWorld() * glm::dvec4(1, 0, 0, 1);
    EXPECT_NEAR(world.x, 1.0, 1e-12);
    EXPECT_NEAR(world.y, 3.0, 1e-12);
    EXPECT_NEAR(world.z, 3.0, 1e-12);
}

TEST(LoadSeries, AbsoluteValuePathsAreAllowed) {
    const auto elsewhere = tstyles_test::freshFolder("absolute_values");
    tstyles_test::writeBytes(elsewhere / "values.raw", tstyles_test::rampBytes(tstyles_test::kBaseVoxels));
    json manifest = tstyles_test::baseManifest();
    manifest["time_steps"][1]["values"]["file"] = (elsewhere / "values.raw").string();
    const auto series =
        tstyles::loadSeries(tstyles_test::writeBaseDataset("absolute", manifest) / "series.json");
    EXPECT_EQ(series.steps[1].valuesFile, elsewhere / "values.raw");
    EXPECT_EQ(series.steps[1].rawRange[1], 23.0);
}

// Two steps on different grids, types and placements; the second with a mask.
tstyles::RawSeries mixedRawSeries() {
    tstyles::RawSeries raw;
    raw.name = "round trip";
    raw.valueRange = {0.0, 100.0};
    tstyles::RawTimeStep first;
    first.time = 0.25;
    first.grid.dims = {2, 3, 4};
    first.grid.spacing = {0.1, 0.2, 0.3};
    first.type = ValueType::UInt8;
    first.bytes = tstyles_test::rampBytes(24);
    tstyles::RawTimeStep second;
    second.time = 1.5;
    second.grid.dims = {3, 2, 2};
    second.grid.spacing = {0.02, 0.02, 0.05};
    second.placement.origin = {0.1, -0.5, 2.0};
    second.placement.rotation = glm::angleAxis(glm::radians(123.0), glm::normalize(glm::dvec3(1, -2, 0.5)));
    second.type = ValueType::Float32;
    second.bytes = tstyles_test::float32Bytes({0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110});
    second.mask = std::vector<std::uint8_t>{0, 1, 1, 0, 0, 1, 1, 0, 0, 0, 1, 1};
    raw.steps = {first, second};
    return raw;
}

TEST(WriteSeries, RoundTripsThroughLoadSeries) {
    const auto folder = tstyles_test::freshFolder("round_trip") / "nested" / "dataset";
    const tstyles::RawSeries raw = mixedRawSeries();
    tstyles::writeSeries(raw, folder);
    const auto series = tstyles::loadSeries(folder / "series.json");

    EXPECT_EQ(series.name, raw.name);
    EXPECT_EQ(series.valueRange, raw.valueRange);
    ASSERT_EQ(series.size(), raw.steps.size());
    for (std::size_t index = 0; index < raw.steps.size(); ++index) {
        SCOPED_TRACE("time-step " + std::to_string(index));
        const auto& written = raw.steps[index];
        const auto& loaded = series.steps[index];
        EXPECT_EQ(loaded.time, written.time);
        EXPECT_EQ(loaded.rectilinear().dims, written.grid.dims);
        EXPECT_EQ(loaded.rectilinear().spacing, written.grid.spacing);
        EXPECT_EQ(loaded.sourceType, written.type);
        EXPECT_EQ(loaded.mask, written.mask);
        const glm::dmat4 expected = written.placement.gridToWorld();
        const glm::dmat4 actual = loaded.placement.gridToWorld();
        for (int column = 0; column < 4; ++column) {
            for (int row = 0; row < 4; ++row) EXPECT_NEAR(actual[column][row], expected[column][row], 1e-9);
        }
    }
    EXPECT_EQ(series.steps[0].density[1], float(1.0 / 100.0));
    EXPECT_EQ(series.steps[1].density[5], 0.5f);
    EXPECT_EQ(series.steps[1].density[11], 1.0f);  // 110 clamps to the range's high end
}

TEST(WriteSeries, NamesFilesByZeroPaddedIndexAndLeavesNoTemporaries) {
    tstyles::RawSeries raw;
    raw.name = "many";
    for (int index = 0; index <= 100; ++index) {
        tstyles::RawTimeStep step;
        step.time = index;
        step.grid.dims = {2, 2, 2};
        step.type = ValueType::UInt8;
        step.bytes = tstyles_test::rampBytes(8);
        if (index == 100) step.mask = std::vector<std::uint8_t>(8, 1);
        raw.steps.push_back(step);
    }
    const auto folder = tstyles_test::freshFolder("padding");
    tstyles::writeSeries(raw, folder);
    EXPECT_TRUE(std::filesystem::exists(folder / "t000.raw"));
    EXPECT_TRUE(std::filesystem::exists(folder / "t100.raw"));
    EXPECT_TRUE(std::filesystem::exists(folder / "t100_mask.raw"));
    // 101 values files, one mask, one manifest: nothing else.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder), {}), 103);

    raw.steps.resize(3);
    const auto small = tstyles_test::freshFolder("padding_small");
    tstyles::writeSeries(raw, small);
    EXPECT_TRUE(std::filesystem::exists(small / "t02.raw"));
}

TEST(WriteSeries, WritesIdentityRotationAsZAxisAndZeroAngle) {
    tstyles::RawSeries raw = mixedRawSeries();
    const auto folder = tstyles_test::freshFolder("identity");
    tstyles::writeSeries(raw, folder);
    std::ifstream in(folder / "series.json");
    const json manifest = json::parse(in);
    const json& rotation = manifest["time_steps"][0]["placement"]["rotation"];
    EXPECT_EQ(rotation["axis"], json({0.0, 0.0, 1.0}));
    EXPECT_EQ(rotation["angle_deg"], 0.0);
    EXPECT_EQ(manifest["time_steps"][1]["values"]["file"], "t01.raw");
    EXPECT_EQ(manifest["time_steps"][1]["mask"]["file"], "t01_mask.raw");
}

TEST(WriteSeries, RejectsASeriesThatCouldNotBeLoaded) {
    tstyles::RawSeries raw = mixedRawSeries();
    raw.steps[1].bytes.pop_back();
    EXPECT_THROW(tstyles::writeSeries(raw, tstyles_test::freshFolder("reject")), std::invalid_argument);
}

}  // namespace
