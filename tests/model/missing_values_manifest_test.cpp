// Missing values and uneven axes in manifests: what loads, what round-trips through writeSeries,
// and every bad spelling reported with the file, the field and the problem.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "test_dataset.h"
#include "tstyles/data/grid_axes.h"
#include "tstyles/data/manifest.h"

namespace {

using nlohmann::json;
using tstyles::isMissing;
using tstyles_test::baseManifest;
using tstyles_test::expectMentions;
using tstyles_test::kBaseVoxels;
using tstyles_test::loadError;
using tstyles_test::writeBaseDataset;

// The base dataset (values 0..23 in both steps) with `missing_value` set to `marker`.
json withMarker(const json& marker) {
    json manifest = baseManifest();
    manifest["missing_value"] = marker;
    return manifest;
}

TEST(MissingValues, RawValuesEqualToTheMarkerAreMissing) {
    json manifest = withMarker(7);
    manifest.erase("value_range");
    const auto series = tstyles::loadSeries(writeBaseDataset("marker", manifest) / "series.json");
    for (const auto& step : series.steps) {
        EXPECT_TRUE(isMissing(step.density[7]));
        EXPECT_FALSE(isMissing(step.density[6]));
        EXPECT_FALSE(isMissing(step.density[8]));
    }
    // The derived range is still 0..23 (7 lies inside it); 23 maps to 1.
    EXPECT_EQ(series.valueRange[0], 0.0);
    EXPECT_EQ(series.valueRange[1], 23.0);
    EXPECT_EQ(series.steps[0].density[23], 1.0f);
}

TEST(MissingValues, TheDerivedValueRangeIgnoresMissingValues) {
    json manifest = withMarker(255);
    manifest.erase("value_range");
    const auto folder = writeBaseDataset("range_ignores", manifest);
    std::vector<std::uint8_t> values = tstyles_test::rampBytes(kBaseVoxels);
    values[3] = 255;  // a fill value far above the data
    tstyles_test::writeBytes(folder / "t00.raw", values);
    const auto series = tstyles::loadSeries(folder / "series.json");
    EXPECT_EQ(series.valueRange[1], 23.0);
    EXPECT_EQ(series.steps[0].rawRange[1], 23.0);
    EXPECT_TRUE(isMissing(series.steps[0].density[3]));
    EXPECT_EQ(series.steps[0].density[23], 1.0f);
}

TEST(MissingValues, AStepWithoutAnyDataHasNoRawRange) {
    json manifest = withMarker(9);
    const auto folder = writeBaseDataset("all_missing_step", manifest);
    tstyles_test::writeBytes(folder / "t01.raw", std::vector<std::uint8_t>(kBaseVoxels, 9));
    const auto series = tstyles::loadSeries(folder / "series.json");
    EXPECT_TRUE(std::isnan(series.steps[1].rawRange[0]));
    for (float density : series.steps[1].density) EXPECT_TRUE(isMissing(density));
}

// NaN in float data is missing declared or not (as in every reader); "missing_value": "NaN" only
// says so. The range leaves it out either way.
TEST(MissingValues, NaNIsMissingDeclaredOrNot) {
    json manifest = baseManifest();
    manifest.erase("value_range");
    manifest["time_steps"][0]["values"]["type"] = "float32";
    std::vector<float> values(kBaseVoxels, 1.0f);
    values[3] = 2.0f;
    values[4] = std::nanf("");
    for (const bool declared : {false, true}) {
        if (declared) manifest["missing_value"] = "NaN";
        const auto folder = writeBaseDataset(declared ? "nan_declared" : "nan_undeclared", manifest);
        tstyles_test::writeBytes(folder / "t00.raw", tstyles_test::float32Bytes(values));
        const auto series = tstyles::loadSeries(folder / "series.json");
        EXPECT_TRUE(isMissing(series.steps[0].density[4])) << "declared: " << declared;
        EXPECT_FALSE(isMissing(series.steps[0].density[5])) << "declared: " << declared;
        EXPECT_EQ(series.steps[0].rawRange, (std::array<double, 2>{1.0, 2.0})) << "declared: " << declared;
    }
}

TEST(MissingValues, Float32MarkerComparesInFloatPrecision) {
    json manifest = withMarker(1e35);
    manifest["time_steps"][0]["values"]["type"] = "float32";
    std::vector<float> values(kBaseVoxels, 2.0f);
    values[0] = 1e35f;
    const auto folder = writeBaseDataset("float_marker", manifest);
    tstyles_test::writeBytes(folder / "t00.raw", tstyles_test::float32Bytes(values));
    const auto series = tstyles::loadSeries(folder / "series.json");
    EXPECT_TRUE(isMissing(series.steps[0].density[0]));
    EXPECT_EQ(series.steps[0].rawRange[1], 2.0);
}

// Value files are decoded a million values per read (raw_values.cpp): a file of several reads
// keeps every value where it belongs, finds the range and the missing values in every read, and
// reports a bad value by its voxel, not by its place in the read.
TEST(MissingValues, AFileOfSeveralReadsDecodesEveryValue) {
    const glm::ivec3 dims{128, 128, 100};  // 1 638 400 values: two reads, the second partial
    const std::size_t count = std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
    json manifest = withMarker(-1);
    manifest.erase("value_range");
    manifest["time_steps"] = {manifest["time_steps"][0]};
    manifest["time_steps"][0].erase("mask");
    manifest["time_steps"][0]["grid"]["dims"] = {dims.x, dims.y, dims.z};
    manifest["time_steps"][0]["values"]["type"] = "float32";
    std::vector<float> values(count);
    for (std::size_t index = 0; index < count; ++index) values[index] = float(index % 1000);
    values[(std::size_t(1) << 20) + 5] = -1.0f;  // missing, in the second read
    values[count - 1] = 5000.0f;                 // the maximum, the last value of the last read
    const auto folder = writeBaseDataset("several_reads", manifest);
    tstyles_test::writeBytes(folder / "t00.raw", tstyles_test::float32Bytes(values));
    const auto series = tstyles::loadSeries(folder / "series.json");
    const auto& step = series.steps[0];
    EXPECT_EQ(step.rawRange[0], 0.0);
    EXPECT_EQ(step.rawRange[1], 5000.0);
    EXPECT_TRUE(isMissing(step.density[(std::size_t(1) << 20) + 5]));
    const std::size_t inSecondRead = (std::size_t(1) << 20) + 123;
    EXPECT_FLOAT_EQ(step.density[inSecondRead], float(inSecondRead % 1000) / 5000.0f);
    EXPECT_EQ(step.density[count - 1], 1.0f);

    values[count - 2] = std::numeric_limits<float>::infinity();  // voxel (126, 127, 99)
    tstyles_test::writeBytes(folder / "t00.raw", tstyles_test::float32Bytes(values));
    expectMentions(loadError(folder / "series.json"), {"time_steps[0].values.file", "Inf", "(126, 127, 99)"});
}

TEST(MissingValues, BadMarkersAndAllMissingAreErrors) {
    const auto folder = writeBaseDataset("bad_marker", withMarker("nan"));
    expectMentions(loadError(folder / "series.json"), {"series.json", "missing_value", "\"NaN\""});
    expectMentions(loadError(writeBaseDataset("marker_array", withMarker({1})) / "series.json"),
                   {"missing_value", "expected a number"});

    json manifest = withMarker(4);
    manifest.erase("value_range");
    const auto allMissing = writeBaseDataset("all_missing", manifest);
    tstyles_test::writeBytes(allMissing / "t00.raw", std::vector<std::uint8_t>(kBaseVoxels, 4));
    tstyles_test::writeBytes(allMissing / "t01.raw", std::vector<std::uint8_t>(kBaseVoxels, 4));
    expectMentions(loadError(allMissing / "series.json"), {"value_range", "missing"});
}

// The base grid is 2 x 3 x 4: an uneven z axis lists four positions.
json withZPositions(const json& positions, const json& zSpacing = nullptr) {
    json manifest = baseManifest();
    manifest["time_steps"][0]["grid"]["positions"] = {{"z", positions}};
    manifest["time_steps"][0]["grid"]["spacing"][2] = zSpacing;
    return manifest;
}

TEST(UnevenAxes, PositionsLoadAndSetTheExtent) {
    const auto series =
        tstyles::loadSeries(writeBaseDataset("uneven", withZPositions({0, 0.5, 1.5, 3.5})) / "series.json");
    const auto& grid = series.steps[0].rectilinear();
    EXPECT_TRUE(grid.isUneven(2));
    EXPECT_FALSE(grid.isUneven(0));
    EXPECT_EQ(grid.axisPositions[2], (std::vector<double>{0, 0.5, 1.5, 3.5}));
    EXPECT_EQ(grid.extent().z, 3.5);
    EXPECT_EQ(grid.extent().x, 0.5);
    EXPECT_DOUBLE_EQ(series.finestSpacing(), 0.25);  // the second step's even z spacing
}

TEST(UnevenAxes, BadPositionsAreErrors) {
    const auto error = [](const json& manifest) { return loadError(writeBaseDataset("bad_uneven", manifest) / "series.json"); };
    expectMentions(error(withZPositions({0, 1, 2})),
                   {"series.json", "time_steps[0].grid.positions.z", "expected 4 node positions", "found 3"});
    expectMentions(error(withZPositions({0, 1, 1, 2})),
                   {"time_steps[0].grid.positions.z[2]", "strictly increasing", "1 follows 1"});
    expectMentions(error(withZPositions({0, 2, 1, 3})), {"positions.z[2]", "strictly increasing"});
    expectMentions(error(withZPositions({0.5, 1, 2, 3})), {"positions.z[0]", "first node must be at 0"});
    expectMentions(error(withZPositions({0, 1, "2", 3})), {"positions.z[2]", "expected a number"});
    expectMentions(error(withZPositions({0, 1, 2, 3}, 0.25)), {"time_steps[0].grid.spacing[2]", "must be null"});

    json unknownAxis = baseManifest();
    unknownAxis["time_steps"][0]["grid"]["positions"] = {{"w", {0, 1}}};
    expectMentions(error(unknownAxis), {"time_steps[0].grid.positions.w", "unknown key"});

    json nullWithoutPositions = baseManifest();
    nullWithoutPositions["time_steps"][1]["grid"]["spacing"][0] = nullptr;
    expectMentions(error(nullWithoutPositions), {"time_steps[1].grid.spacing[0]", "positions.x"});
}

TEST(UnevenAxes, NodePositionsAndFractionalIndicesAreInverse) {
    tstyles::RectilinearGrid grid;
    grid.dims = {2, 2, 4};
    grid.spacing = {0.5, 0.5, 1.0};
    grid.axisPositions[2] = {0.0, 0.5, 1.5, 3.5};
    EXPECT_DOUBLE_EQ(tstyles::fractionalIndex(grid, 2, 1.0), 1.5);
    EXPECT_DOUBLE_EQ(tstyles::fractionalIndex(grid, 2, 2.5), 2.5);
    EXPECT_DOUBLE_EQ(tstyles::fractionalIndex(grid, 2, 3.5), 3.0);
    EXPECT_DOUBLE_EQ(tstyles::fractionalIndex(grid, 0, 0.25), 0.5);
    EXPECT_DOUBLE_EQ(tstyles::nodePosition(grid, 2, 2.25), 2.0);
    EXPECT_DOUBLE_EQ(tstyles::finestSpacing(grid), 0.5);
    for (double index : {0.0, 0.3, 1.0, 1.7, 2.9, 3.0})
        EXPECT_NEAR(tstyles::fractionalIndex(grid, 2, tstyles::nodePosition(grid, 2, index)), index, 1e-12);
}

TEST(WriteSeries, RoundTripsMissingValuesAndUnevenAxes) {
    for (const double marker : {200.0, double(std::nanf(""))}) {
        tstyles::RawSeries raw;
        raw.name = "uneven with gaps";
        raw.valueRange = {0.0, 100.0};
        raw.missingValue = marker;
        tstyles::RawTimeStep step;
        step.time = 0.0;
        step.grid.dims = {2, 2, 3};
        step.grid.spacing = {0.1, 0.1, 1.0};
        step.grid.axisPositions[2] = {0.0, 0.25, 1.0};
        step.type = tstyles::ValueType::Float32;
        const float gap = std::isnan(marker) ? std::nanf("") : float(marker);
        step.bytes = tstyles_test::float32Bytes({0, 10, gap, 30, 40, 50, 60, 70, 80, gap, 100, 50});
        raw.steps = {step};
        const auto folder = tstyles_test::freshFolder("round_trip_missing");
        tstyles::writeSeries(raw, folder);
        const auto series = tstyles::loadSeries(folder / "series.json");
        const auto& grid = series.steps[0].rectilinear();
        EXPECT_EQ(grid.axisPositions[2], step.grid.axisPositions[2]);
        EXPECT_FALSE(grid.isUneven(0));
        EXPECT_EQ(grid.spacing.x, 0.1);
        EXPECT_TRUE(isMissing(series.steps[0].density[2]));
        EXPECT_TRUE(isMissing(series.steps[0].density[9]));
        EXPECT_EQ(series.steps[0].density[1], 0.1f);
        EXPECT_EQ(series.steps[0].rawRange[1], 100.0);
    }
}

}  // namespace
