// Every kind of bad dataset is an InputError naming the file, the field and the problem.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "test_dataset.h"
#include "tstyles/data/manifest.h"

namespace {

using nlohmann::json;
using tstyles_test::baseManifest;
using tstyles_test::expectMentions;
using tstyles_test::loadError;
using tstyles_test::writeBaseDataset;

// The load error of the base dataset with the value at `pointer` (e.g. "/time_steps/0/time") set.
std::string errorWhenSet(const std::string& pointer, const json& value) {
    json manifest = baseManifest();
    manifest[json::json_pointer(pointer)] = value;
    return loadError(writeBaseDataset("set", manifest) / "series.json");
}

// The load error of the base dataset with the key at `pointer` removed.
std::string errorWhenErased(const std::string& pointer) {
    const json::json_pointer key(pointer);
    json manifest = baseManifest();
    manifest[key.parent_pointer()].erase(key.back());
    return loadError(writeBaseDataset("erased", manifest) / "series.json");
}

TEST(ManifestErrors, TheBaseDatasetLoads) {
    EXPECT_NO_THROW(tstyles::loadSeries(writeBaseDataset("base_ok", baseManifest()) / "series.json"));
}

TEST(ManifestErrors, MissingManifest) {
    const auto folder = tstyles_test::freshFolder("missing_manifest");
    expectMentions(loadError(folder / "nope.json"), {"nope.json", "not found"});
    // A folder stands for its series.json, which is missing here.
    expectMentions(loadError(folder), {"series.json", "not found"});
}

TEST(ManifestErrors, NotJsonGivesTheParserPosition) {
    const auto folder = tstyles_test::freshFolder("not_json");
    tstyles_test::writeText(folder / "series.json", "{\n  \"format\": \"tstyles-series\",\n  oops\n}");
    expectMentions(loadError(folder / "series.json"), {"series.json", "not valid JSON", "line 3"});
}

TEST(ManifestErrors, NumbersBeyondDoubleAreRejectedByTheParser) {
    auto text = baseManifest().dump();
    text.replace(text.find("[1.0,2.0,3.0]"), 13, "[1.0,1e999,3.0]");
    const auto folder = writeBaseDataset("huge_number", baseManifest());
    tstyles_test::writeText(folder / "series.json", text);
    expectMentions(loadError(folder / "series.json"), {"series.json", "not valid JSON", "1e999"});
}

TEST(ManifestErrors, TopLevelMustBeAnObject) {
    const auto folder = tstyles_test::freshFolder("array_top");
    tstyles_test::writeText(folder / "series.json", "[1, 2]");
    expectMentions(loadError(folder / "series.json"), {"series.json", "expected an object", "array"});
}

TEST(ManifestErrors, WrongFormatOrVersion) {
    expectMentions(errorWhenSet("/format", "other"), {"series.json", "format", "tstyles-series", "other"});
    expectMentions(errorWhenSet("/version", 2), {"series.json", "version", "unsupported version 2"});
    expectMentions(errorWhenErased("/format"), {"series.json", "format", "missing; this key is required"});
}

TEST(ManifestErrors, UnknownKeysAnywhere) {
    expectMentions(errorWhenSet("/colour", "red"), {"series.json", "colour", "unknown key"});
    expectMentions(errorWhenSet("/time_steps/0/placment", json::object()),
                   {"series.json", "time_steps[0].placment: unknown key", "placement"});
    expectMentions(errorWhenSet("/time_steps/1/placement/rotation/angle", 1),
                   {"time_steps[1].placement.rotation.angle", "unknown key"});
    expectMentions(errorWhenSet("/time_steps/0/values/endian", "big"),
                   {"time_steps[0].values.endian", "unknown key"});
}

TEST(ManifestErrors, WrongTypes) {
    expectMentions(errorWhenSet("/time_steps/0/time", "zero"),
                   {"series.json", "time_steps[0].time", "expected a number", "got a string"});
    expectMentions(errorWhenSet("/time_steps/1/grid/dims", "64"),
                   {"time_steps[1].grid.dims", "expected an array"});
    expectMentions(errorWhenSet("/time_steps", json::object()),
                   {"time_steps", "expected an array", "object"});
    expectMentions(errorWhenSet("/name", 7), {"name", "expected a string"});
    expectMentions(errorWhenSet("/time_steps/0/grid/dims/2", 2.5),
                   {"time_steps[0].grid.dims[2]", "expected an integer"});
    expectMentions(errorWhenSet("/time_steps/0/placement/origin", {1, 2}),
                   {"time_steps[0].placement.origin", "3 numbers"});
    expectMentions(errorWhenSet("/climatology", 1), {"series.json", "climatology", "expected true or false", "number"});
}

TEST(ManifestErrors, MissingRequiredKeys) {
    expectMentions(errorWhenErased("/time_steps/0/grid"),
                   {"series.json", "time_steps[0].grid", "missing; this key is required"});
    expectMentions(errorWhenErased("/time_steps/1/time"), {"time_steps[1].time", "missing; this key is required"});
    expectMentions(errorWhenErased("/time_steps/1/values/file"),
                   {"time_steps[1].values.file", "missing; this key is required"});
    expectMentions(errorWhenErased("/time_steps/0/placement/rotation/angle_deg"),
                   {"time_steps[0].placement.rotation.angle_deg", "missing; this key is required"});
}

TEST(ManifestErrors, GridNeedsTwoSamplesPerAxisAndPositiveSpacing) {
    expectMentions(errorWhenSet("/time_steps/0/grid/dims/1", 1),
                   {"series.json", "time_steps[0].grid.dims[1]", "at least 2", "found 1"});
    expectMentions(errorWhenSet("/time_steps/1/grid/dims/0", 0),
                   {"time_steps[1].grid.dims[0]", "at least 2"});
    expectMentions(errorWhenSet("/time_steps/0/grid/dims", {1 << 20, 1 << 20, 1 << 20}),
                   {"time_steps[0].grid.dims", "too many voxels"});
    expectMentions(errorWhenSet("/time_steps/0/grid/spacing/2", 0.0),
                   {"time_steps[0].grid.spacing[2]", "positive"});
    expectMentions(errorWhenSet("/time_steps/0/grid/spacing/0", -1),
                   {"time_steps[0].grid.spacing[0]", "positive", "-1"});
    expectMentions(errorWhenSet("/time_steps/0/grid/type", "curvilinear"),
                   {"time_steps[0].grid.type", "unknown grid type", "curvilinear"});
}

TEST(ManifestErrors, ZeroRotationAxis) {
    expectMentions(errorWhenSet("/time_steps/1/placement/rotation/axis", {0, 0, 0}),
                   {"series.json", "time_steps[1].placement.rotation.axis", "zero"});
}

TEST(ManifestErrors, UnknownValueType) {
    expectMentions(errorWhenSet("/time_steps/0/values/type", "int64"),
                   {"series.json", "time_steps[0].values.type", "unknown value type", "int64", "uint16"});
}

TEST(ManifestErrors, TimesMustIncreaseStrictly) {
    expectMentions(errorWhenSet("/time_steps/1/time", 0.0),
                   {"series.json", "time_steps[1].time", "strictly increasing"});
    expectMentions(errorWhenSet("/time_steps/1/time", -1.0),
                   {"time_steps[1].time", "strictly increasing", "-1"});
}

TEST(ManifestErrors, EmptyTimeSteps) {
    expectMentions(errorWhenSet("/time_steps", json::array()), {"series.json", "time_steps", "at least one"});
}

TEST(ManifestErrors, BadValueRange) {
    expectMentions(errorWhenSet("/value_range", {5, 5}), {"series.json", "value_range", "less than"});
    expectMentions(errorWhenSet("/value_range", {10, 0}), {"value_range", "less than", "[10, 0]"});
    expectMentions(errorWhenSet("/value_range", {1}), {"value_range", "[low, high]"});
    expectMentions(errorWhenSet("/value_range", {"a", 1}), {"value_range[0]", "expected a number"});
}

TEST(ManifestErrors, ConstantDataWithoutValueRangeAsksForOne) {
    json manifest = baseManifest();
    manifest.erase("value_range");
    const auto folder = writeBaseDataset("constant", manifest);
    tstyles_test::writeBytes(folder / "t00.raw", std::vector<std::uint8_t>(tstyles_test::kBaseVoxels, 7));
    tstyles_test::writeBytes(folder / "t01.raw", std::vector<std::uint8_t>(tstyles_test::kBaseVoxels, 7));
    expectMentions(loadError(folder / "series.json"), {"series.json", "value_range", "7", "give"});
}

TEST(ManifestErrors, MissingValueFileNamesFileAndTimeStep) {
    const auto folder = writeBaseDataset("missing_values", baseManifest());
    std::filesystem::remove(folder / "t01.raw");
    expectMentions(loadError(folder / "series.json"),
                   {"series.json", "time_steps[1].values.file", "t01.raw", "time-step 1", "not found"});
}

TEST(ManifestErrors, ValueFileSizeMustMatchDimsAndType) {
    const auto folder = writeBaseDataset("truncated", baseManifest());
    tstyles_test::writeBytes(folder / "t01.raw", tstyles_test::rampBytes(23));
    expectMentions(loadError(folder / "series.json"),
                   {"time_steps[1].values.file", "t01.raw", "truncated", "expected 24 bytes", "found 23"});
    tstyles_test::writeBytes(folder / "t01.raw", tstyles_test::rampBytes(25));
    expectMentions(loadError(folder / "series.json"), {"t01.raw", "too large", "expected 24", "found 25"});

    // The same 24 bytes are too few once the manifest says uint16.
    json manifest = baseManifest();
    manifest["time_steps"][0]["values"]["type"] = "uint16";
    expectMentions(loadError(writeBaseDataset("wrong_type", manifest) / "series.json"),
                   {"t00.raw", "truncated", "expected 48 bytes", "uint16", "found 24"});
}

TEST(ManifestErrors, NonFiniteFloatNamesTheFirstBadVoxel) {
    json manifest = baseManifest();
    manifest["time_steps"][0]["values"]["type"] = "float32";
    const auto folder = writeBaseDataset("inf", manifest);
    std::vector<float> values(tstyles_test::kBaseVoxels, 1.0f);
    // Index 7 in a 2 x 3 x 4 grid is x = 1, y = 0, z = 1; the later Inf must not be the one named.
    values[7] = -std::numeric_limits<float>::infinity();
    values[20] = std::numeric_limits<float>::infinity();
    tstyles_test::writeBytes(folder / "t00.raw", tstyles_test::float32Bytes(values));
    expectMentions(loadError(folder / "series.json"), {"series.json", "time_steps[0].values.file", "t00.raw",
                                                       "time-step 0", "(-Inf)", "(1, 0, 1)", "only NaN"});

    values[7] = 1.0f;
    tstyles_test::writeBytes(folder / "t00.raw", tstyles_test::float32Bytes(values));
    // Index 20 is x = 0, y = 1, z = 3.
    expectMentions(loadError(folder / "series.json"), {"t00.raw", "Inf", "(0, 1, 3)"});
}

TEST(ManifestErrors, MaskSizeMustMatchDims) {
    const auto folder = writeBaseDataset("mask_size", baseManifest());
    tstyles_test::writeBytes(folder / "t00_mask.raw", std::vector<std::uint8_t>(10, 1));
    expectMentions(loadError(folder / "series.json"), {"series.json", "time_steps[0].mask.file",
                                                       "t00_mask.raw", "mask", "truncated", "expected 24"});
    std::filesystem::remove(folder / "t00_mask.raw");
    expectMentions(loadError(folder / "series.json"), {"t00_mask.raw", "not found"});
}

}  // namespace
