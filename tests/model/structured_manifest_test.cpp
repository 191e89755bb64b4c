// Structured grids in manifests: written and read back with shared coordinates, and bad grids
// refused with the time-step, the field and the problem.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "test_dataset.h"
#include "tstyles/data/manifest.h"
#include "tstyles/data/series_summary.h"
#include "tstyles/data/warped_box.h"

namespace {

using tstyles::RawSeries;
using tstyles::RawTimeStep;

RawSeries warpedSeries(int steps) {
    const tstyles::StructuredGrid grid = tstyles::WarpedBox{}.grid();
    RawSeries series;
    series.name = "warped";
    series.valueRange = {0.0, 255.0};
    for (int index = 0; index < steps; ++index) {
        RawTimeStep step;
        step.time = index;
        step.structured = grid;
        step.type = tstyles::ValueType::UInt8;
        step.bytes = tstyles_test::rampBytes(grid.voxelCount());
        series.steps.push_back(step);
    }
    return series;
}

std::string loadError(const std::filesystem::path& manifest) {
    try {
        tstyles::loadSeries(manifest);
    } catch (const tstyles::InputError& error) {
        return error.what();
    }
    return "no error";
}

TEST(StructuredManifest, RoundTripsAndSharesOneGridBetweenTimeSteps) {
    const auto folder = tstyles_test::freshFolder("structured_roundtrip");
    tstyles::writeSeries(warpedSeries(2), folder);
    EXPECT_TRUE(std::filesystem::exists(folder / "grid00.xyz.f32"));
    EXPECT_FALSE(std::filesystem::exists(folder / "grid01.xyz.f32"));
    const tstyles::Series series = tstyles::loadSeries(folder);
    ASSERT_EQ(series.size(), 2u);
    const tstyles::StructuredGrid* first = series.steps[0].structured();
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first->nodes, series.steps[1].structured()->nodes);  // one grid, one inverse map
    EXPECT_EQ(*first->nodes, *tstyles::WarpedBox{}.grid().nodes);
    EXPECT_EQ(series.steps[1].density[17], 17.0f / 255.0f);
    EXPECT_EQ(tstyles::distinctStructuredGrids(series).size(), 1u);
    const std::string summary = tstyles::describeSeries(series);
    EXPECT_NE(summary.find("structured 17x17x9"), std::string::npos) << summary;
    EXPECT_NE(summary.find("inverse map 33x33x17"), std::string::npos) << summary;
}

TEST(StructuredManifest, ACoordinatesFileOfTheWrongSizeNamesTheTimeStep) {
    const auto folder = tstyles_test::freshFolder("structured_truncated");
    tstyles::writeSeries(warpedSeries(1), folder);
    std::filesystem::resize_file(folder / "grid00.xyz.f32", 100);
    const std::string message = loadError(folder);
    EXPECT_NE(message.find("time_steps[0].grid.coordinates.file: coordinates file"), std::string::npos) << message;
    EXPECT_NE(message.find("of time-step 0 is truncated: expected 31212 bytes (17 x 17 x 9 nodes, 3 float32 each), "
                           "found 100 bytes"),
              std::string::npos)
        << message;
}

TEST(StructuredManifest, AnInvertedCellNamesTheTimeStepAndTheCell) {
    RawSeries series = warpedSeries(1);
    std::vector<glm::vec3> nodes = *series.steps[0].structured->nodes;
    const auto& grid = *series.steps[0].structured;
    std::swap(nodes[grid.nodeIndex(3, 4, 5)], nodes[grid.nodeIndex(3, 5, 5)]);
    series.steps[0].structured = tstyles::makeStructuredGrid(grid.dims, nodes);
    const auto folder = tstyles_test::freshFolder("structured_inverted");
    tstyles::writeSeries(series, folder);
    const std::string message = loadError(folder);
    EXPECT_NE(message.find("time_steps[0].grid.coordinates.file: grid"), std::string::npos) << message;
    EXPECT_NE(message.find("of time-step 0: cell (2, 4, 4) is inverted"), std::string::npos) << message;
}

TEST(StructuredManifest, UnknownGridTypesListTheKnownOnes) {
    const auto folder = tstyles_test::freshFolder("structured_unknown_type");
    tstyles::writeSeries(warpedSeries(1), folder);
    std::ifstream in(folder / "series.json");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("\"structured\""), 12, "\"curvy\"");
    tstyles_test::writeText(folder / "series.json", text);
    const std::string message = loadError(folder);
    EXPECT_NE(message.find("unknown grid type 'curvy' (known: rectilinear, structured, beam)"), std::string::npos) << message;
}

}  // namespace
