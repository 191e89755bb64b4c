// Cutting a series to one process's block: the kept nodes are the ones the block's samples and
// gradients read, at the same world positions with the same values.
#include "tstyles/data/series_crop.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_dataset.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/beam_geometry.h"
#include "tstyles/data/density_sampling.h"
#include "tstyles/data/manifest.h"
#include "tstyles/data/structured_grid.h"

namespace tstyles {
namespace {

// A value that tells nodes apart: linear in the world position.
float valueAt(const glm::dvec3& world) { return float(0.1 * world.x + 0.01 * world.y + 0.001 * world.z); }

// One rectilinear time-step of dims nodes, `spacing` apart, at `placement`, holding valueAt.
TimeStep linearStep(glm::ivec3 dims, glm::dvec3 spacing, const Placement& placement,
                    std::array<std::vector<double>, 3> uneven = {}) {
    TimeStep step;
    RectilinearGrid grid;
    grid.dims = dims;
    grid.spacing = spacing;
    grid.axisPositions = std::move(uneven);
    const auto local = [&](glm::ivec3 node) {
        glm::dvec3 position = glm::dvec3(node) * spacing;
        for (int axis = 0; axis < 3; ++axis)
            if (grid.isUneven(axis)) position[axis] = grid.axisPositions[std::size_t(axis)][std::size_t(node[axis])];
        return position;
    };
    const glm::dmat4 toWorld = placement.gridToWorld();
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x)
                step.density.push_back(valueAt(glm::dvec3(toWorld * glm::dvec4(local({x, y, z}), 1.0))));
    step.mask = std::vector<std::uint8_t>(step.density.size(), 1);
    step.grid = grid;
    step.placement = placement;
    return step;
}

// Every kept node holds the value of its world position.
void expectValuesFollowTheirNodes(const TimeStep& step) {
    const RectilinearGrid& grid = step.rectilinear();
    const glm::dmat4 toWorld = step.placement.gridToWorld();
    std::size_t index = 0;
    for (int z = 0; z < grid.dims.z; ++z)
        for (int y = 0; y < grid.dims.y; ++y)
            for (int x = 0; x < grid.dims.x; ++x, ++index) {
                glm::dvec3 local = glm::dvec3(x, y, z) * grid.spacing;
                for (int axis = 0; axis < 3; ++axis)
                    if (grid.isUneven(axis)) local[axis] = grid.axisPositions[std::size_t(axis)][std::size_t(glm::ivec3(x, y, z)[axis])];
                ASSERT_NEAR(step.density[index], valueAt(glm::dvec3(toWorld * glm::dvec4(local, 1.0))), 1e-5);
            }
    ASSERT_EQ(step.mask->size(), step.density.size());
}

TEST(SeriesCrop, KeepsTheCellsTheBoxTouchesPlusGhostNodes) {
    Series series;
    series.steps.push_back(linearStep({11, 6, 5}, glm::dvec3(0.1), Placement{}));
    // x in [0.25, 0.45]: cells 2..4 (nodes 2..5), two ghost nodes on each side: nodes 0..7.
    const Series block = cropSeriesToBox(series, Bounds{{0.25, -1.0, -1.0}, {0.45, 1.0, 1.0}}, 2);
    const TimeStep& step = block.steps[0];
    EXPECT_EQ(step.rectilinear().dims, glm::ivec3(8, 6, 5));
    EXPECT_NEAR(step.placement.origin.x, 0.0, 1e-12);
    expectValuesFollowTheirNodes(step);
    // Further in, the first kept node moves: x in [0.55, 0.65] keeps nodes 3..9.
    const Series inner = cropSeriesToBox(series, Bounds{{0.55, -1.0, -1.0}, {0.65, 1.0, 1.0}}, 2);
    EXPECT_EQ(inner.steps[0].rectilinear().dims.x, 7);
    EXPECT_NEAR(inner.steps[0].placement.origin.x, 0.3, 1e-12);
    expectValuesFollowTheirNodes(inner.steps[0]);
}

TEST(SeriesCrop, RotatedPlacementsAndUnevenAxesKeepTheirWorldPositions) {
    Placement placement;
    placement.origin = {1.0, 2.0, 3.0};
    placement.rotation = fromAxisAngle({{0.0, 0.0, 1.0}, 90.0});
    Series series;
    series.steps.push_back(linearStep({9, 7, 6}, glm::dvec3(0.2, 0.1, 0.3), placement,
                                      {std::vector<double>{}, std::vector<double>{},
                                       std::vector<double>{0.0, 0.1, 0.3, 0.7, 1.2, 2.0}}));
    const Bounds box{{0.62, 2.1, 3.35}, {0.88, 2.9, 3.8}};
    const Series block = cropSeriesToBox(series, box, 1);
    const TimeStep& step = block.steps[0];
    const RectilinearGrid& grid = step.rectilinear();
    EXPECT_LT(grid.dims.x, 9);
    EXPECT_LT(grid.dims.y, 7);
    EXPECT_LT(grid.dims.z, 6);
    EXPECT_DOUBLE_EQ(grid.axisPositions[2].front(), 0.0);
    expectValuesFollowTheirNodes(step);
    // The kept grid still covers the box.
    const Bounds kept = block.worldBounds(0);
    EXPECT_TRUE(glm::all(glm::lessThanEqual(kept.lower, box.lower + 1e-12)));
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(kept.upper, box.upper - 1e-12)));
}

TEST(SeriesCrop, ATimeStepOutsideTheBoxKeepsItsNearestCell) {
    Series series;
    series.steps.push_back(linearStep({5, 5, 5}, glm::dvec3(0.1), Placement{}));
    Placement far;
    far.origin = {10.0, 0.0, 0.0};
    series.steps.push_back(linearStep({5, 5, 5}, glm::dvec3(0.1), far));
    const Series block = cropSeriesToBox(series, Bounds{{0.0, 0.0, 0.0}, {0.4, 0.4, 0.4}}, 2);
    ASSERT_EQ(block.size(), 2u);  // time-step indices keep their meaning
    EXPECT_EQ(block.steps[1].rectilinear().dims.x, 2);
    EXPECT_NEAR(block.steps[1].placement.origin.x, 10.0, 1e-12);
    expectValuesFollowTheirNodes(block.steps[1]);
}

// A plain time-step and a turned one with an uneven z axis.
std::vector<TimeStep> plainAndTurnedUnevenSteps() {
    Placement turned;
    turned.origin = {0.3, -0.2, 0.1};
    turned.rotation = fromAxisAngle({{1.0, 1.0, 0.0}, 35.0});
    return {linearStep({11, 6, 5}, glm::dvec3(0.1), Placement{}),
            linearStep({9, 7, 6}, glm::dvec3(0.2, 0.1, 0.3), turned,
                       {std::vector<double>{}, std::vector<double>{}, std::vector<double>{0.0, 0.1, 0.3, 0.7, 1.2, 2.0}})};
}

// Blocks through both time-steps, in the corner of both, and outside both.
const std::vector<Bounds> kBlockBoxes = {Bounds{{0.25, -1.0, -1.0}, {0.45, 1.0, 1.0}},
                                         Bounds{{0.0, 0.0, 0.0}, {0.2, 0.2, 0.2}},
                                         Bounds{{5.0, 5.0, 5.0}, {6.0, 6.0, 6.0}}};

// What a reader checks against the memory cap before it reads (croppedVoxelCount, from the grid
// and placement alone) is what cutting the read time-step keeps.
TEST(SeriesCrop, TheVoxelCountKnownBeforeReadingIsWhatTheCutKeeps) {
    const std::vector<TimeStep> steps = plainAndTurnedUnevenSteps();
    for (const Bounds& box : kBlockBoxes) {
        for (std::size_t index = 0; index < steps.size(); ++index) {
            TimeStep outline = withoutValues(steps[index]);
            TimeStep cut = steps[index];
            const std::size_t expected = croppedVoxelCount(outline, box, 2);
            cropTimeStepToBox(cut, box, 2);
            EXPECT_EQ(expected, cut.density.size()) << "time-step " << index;
            EXPECT_EQ(expected, gridVoxelCount(cut.grid));
            expectValuesFollowTheirNodes(cut);
        }
    }
}

// Reading only a block of each time-step (loadSeries with nodesToRead, as readManifestBlock does)
// gives what reading the whole series and cutting it gives: the same values, masks, grids and
// placements, to the bit.
TEST(SeriesCrop, ReadingOnlyTheBlockIsCuttingTheWholeSeries) {
    const std::vector<TimeStep> steps = plainAndTurnedUnevenSteps();
    RawSeries raw;
    raw.name = "blocks";
    raw.valueRange = {-1.0, 1.0};
    for (std::size_t index = 0; index < steps.size(); ++index) {
        RawTimeStep step;
        step.time = double(index);
        step.grid = steps[index].rectilinear();
        step.placement = steps[index].placement;
        step.type = ValueType::Float32;
        step.bytes.resize(steps[index].density.size() * sizeof(float));
        std::memcpy(step.bytes.data(), steps[index].density.data(), step.bytes.size());
        step.mask = std::vector<std::uint8_t>(steps[index].density.size());
        for (std::size_t voxel = 0; voxel < step.mask->size(); ++voxel) (*step.mask)[voxel] = std::uint8_t(voxel);
        raw.steps.push_back(std::move(step));
    }
    const std::filesystem::path folder = tstyles_test::freshFolder("series_crop_block_reading");
    writeSeries(raw, folder);
    const Series whole = loadSeries(folder / "series.json");
    for (const Bounds& box : kBlockBoxes) {
        ManifestLimits limits;
        limits.nodesToRead = [&](std::size_t, const TimeStep& outline) { return nodesKeptOf(outline, box, 2); };
        limits.afterStepRead = [&](std::size_t, TimeStep& step) { cropTimeStepGridToBox(step, box, 2); };
        for (const TimeStep& step : whole.steps) limits.keptVoxels += croppedVoxelCount(step, box, 2);
        const Series block = loadSeries(folder / "series.json", limits);
        const Series cut = cropSeriesToBox(whole, box, 2);
        ASSERT_EQ(block.size(), cut.size());
        for (std::size_t index = 0; index < cut.size(); ++index) {
            const TimeStep& read = block.steps[index];
            const TimeStep& expected = cut.steps[index];
            EXPECT_EQ(read.density, expected.density) << "time-step " << index;
            EXPECT_EQ(*read.mask, *expected.mask) << "time-step " << index;
            EXPECT_EQ(read.rectilinear().dims, expected.rectilinear().dims);
            EXPECT_EQ(read.rectilinear().axisPositions, expected.rectilinear().axisPositions);
            EXPECT_EQ(read.placement.origin, expected.placement.origin);
        }
    }
}

// Where the manifest gives the value range, a block reads only its rows: its raw range is the
// block's, and a bad value is found by the block that holds it and no other. Without the range,
// every block reads the files through, as the range needs every value, and finds it anywhere.
TEST(SeriesCrop, AGivenValueRangeReadsOnlyTheBlocksRows) {
    RawSeries raw;
    raw.name = "rows";
    raw.valueRange = {0.0, 15.0};
    RawTimeStep step;
    step.grid.dims = {16, 4, 4};
    step.grid.spacing = glm::dvec3(1.0);
    step.type = ValueType::Float32;
    std::vector<float> values;
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 16; ++x) values.push_back(float(x));
    values[15] = std::numeric_limits<float>::infinity();  // node (15, 0, 0)
    step.bytes.resize(values.size() * sizeof(float));
    std::memcpy(step.bytes.data(), values.data(), step.bytes.size());
    raw.steps.push_back(std::move(step));
    const std::filesystem::path folder = tstyles_test::freshFolder("series_crop_block_rows");
    writeSeries(raw, folder);
    const auto readBlock = [&](const Bounds& box) {
        ManifestLimits limits;
        limits.nodesToRead = [&](std::size_t, const TimeStep& outline) { return nodesKeptOf(outline, box, 2); };
        limits.afterStepRead = [&](std::size_t, TimeStep& kept) { cropTimeStepGridToBox(kept, box, 2); };
        limits.keptVoxels = 16 * 4 * 4;
        return loadSeries(folder / "series.json", limits);
    };
    const Bounds left{{0.0, 0.0, 0.0}, {4.0, 3.0, 3.0}};  // nodes 0..4, and two ghost nodes: 0..6
    const Series block = readBlock(left);
    EXPECT_EQ(block.steps[0].rawRange, (std::array<double, 2>{0.0, 6.0}));
    EXPECT_EQ(block.valueRange, (std::array<double, 2>{0.0, 15.0}));
    try {
        readBlock(Bounds{{12.0, 0.0, 0.0}, {15.0, 3.0, 3.0}});
        ADD_FAILURE() << "the block that holds the Inf read it";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("non-finite value (Inf) at voxel (x, y, z) = (15, 0, 0)"),
                  std::string::npos)
            << error.what();
    }

    // The same files without "value_range": the left block reads them through and finds the Inf.
    nlohmann::ordered_json manifest = nlohmann::ordered_json::parse(std::ifstream(folder / "series.json"));
    ASSERT_EQ(manifest.erase("value_range"), 1u);
    std::ofstream(folder / "series.json") << manifest.dump(2);
    EXPECT_THROW(readBlock(left), InputError);
}

// A sonar ping: `azimuths` x `elevations` beams over +-30 and +-15 degrees, ranges 1 to 9 m,
// holding valueAt of each node's world position.
TimeStep beamStep(int azimuths, int elevations, int ranges, const Placement& placement) {
    BeamGrid beams;
    beams.dims = {azimuths, elevations, ranges};
    beams.azimuthDeg = evenBeamAngles(-30.0, 30.0, azimuths);
    beams.elevationDeg = evenBeamAngles(-15.0, 15.0, elevations);
    beams.minRange = 1.0;
    beams.maxRange = 9.0;
    TimeStep step;
    step.grid = beams;
    step.placement = placement;
    const glm::dmat4 toWorld = placement.gridToWorld();
    for (int k = 0; k < ranges; ++k)
        for (int j = 0; j < elevations; ++j)
            for (int i = 0; i < azimuths; ++i)
                step.density.push_back(
                    valueAt(glm::dvec3(toWorld * glm::dvec4(beamSamplePosition(beams, i, j, k), 1.0))));
    step.mask = std::vector<std::uint8_t>(step.density.size(), 1);
    return step;
}

// A block cuts a beam grid to the beams and range bins its box needs: the kept nodes sit where they
// sat, with their values, and every point of the box samples what it samples in the whole ping,
// even without ghost nodes and with the ping turned; a box beside the fan keeps one cell.
TEST(SeriesCrop, BeamGridsKeepTheBeamsAndRangesTheBoxNeeds) {
    Placement turned;
    turned.origin = {0.3, -0.2, 0.1};
    turned.rotation = glm::angleAxis(glm::radians(25.0), glm::normalize(glm::dvec3(0.2, 1.0, 0.3)));
    for (const Placement& placement : {Placement{}, turned}) {
        const TimeStep whole = beamStep(31, 13, 81, placement);
        const glm::dmat4 toWorld = placement.gridToWorld();
        const Bounds box{glm::dvec3(toWorld * glm::dvec4(-0.8, -0.5, 4.0, 1.0)) - 0.7,
                         glm::dvec3(toWorld * glm::dvec4(-0.8, -0.5, 4.0, 1.0)) + 0.7};
        for (int ghost : {0, 2}) {
            SCOPED_TRACE("ghost nodes " + std::to_string(ghost));
            TimeStep cut = whole;
            cropTimeStepToBox(cut, box, ghost);
            const BeamGrid& beams = cut.beam();
            EXPECT_LT(cut.density.size(), whole.density.size() / 4);
            EXPECT_EQ(cut.density.size(), croppedVoxelCount(whole, box, ghost));
            EXPECT_EQ(cut.mask->size(), cut.density.size());
            std::size_t index = 0;
            for (int k = 0; k < beams.dims.z; ++k)
                for (int j = 0; j < beams.dims.y; ++j)
                    for (int i = 0; i < beams.dims.x; ++i, ++index) {
                        const glm::dvec3 world(toWorld * glm::dvec4(beamSamplePosition(beams, i, j, k), 1.0));
                        ASSERT_NEAR(cut.density[index], valueAt(world), 1e-5) << i << " " << j << " " << k;
                    }
            int inside = 0;
            for (int z = 0; z <= 20; ++z)
                for (int y = 0; y <= 20; ++y)
                    for (int x = 0; x <= 20; ++x) {
                        const glm::dvec3 at = box.lower + glm::dvec3(x, y, z) / 20.0 * box.size();
                        const std::optional<double> expected = sampleDensity(whole, at);
                        if (!expected) continue;
                        ++inside;
                        const std::optional<double> sampled = sampleDensity(cut, at);
                        ASSERT_TRUE(sampled.has_value()) << "a point of the box left out of the cut ping";
                        ASSERT_NEAR(*sampled, *expected, 1e-6);
                    }
            EXPECT_GT(inside, 5000);  // the box lies mostly inside the fan
        }
    }
    TimeStep beside = beamStep(31, 13, 81, Placement{});
    cropTimeStepToBox(beside, Bounds{{20.0, 20.0, 20.0}, {21.0, 21.0, 21.0}}, 2);
    EXPECT_EQ(beside.beam().dims, glm::ivec3(4, 4, 4));  // the first cell and two ghost nodes beyond it
}

// A structured grid stays whole in every block (the clip box splits its samples instead), and
// the voxel count known before reading says so.
TEST(SeriesCrop, StructuredGridsAreKeptWhole) {
    TimeStep warped;
    std::vector<glm::vec3> nodes;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) nodes.emplace_back(float(i) + 0.1f * float(j), float(j), float(k));
    warped.grid = makeStructuredGrid({2, 2, 2}, std::move(nodes));
    warped.density = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f};
    const Bounds box{{0.0, 0.0, 0.0}, {0.05, 0.05, 0.05}};
    EXPECT_EQ(croppedVoxelCount(warped, box, 2), 8u);
    EXPECT_FALSE(nodesKeptOf(warped, box, 2).has_value());
    TimeStep cut = warped;
    cropTimeStepToBox(cut, box, 2);
    EXPECT_EQ(cut.density, warped.density);
    EXPECT_TRUE(std::holds_alternative<StructuredGrid>(cut.grid));
}

}  // namespace
}  // namespace tstyles
