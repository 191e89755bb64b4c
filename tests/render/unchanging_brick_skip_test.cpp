// Largest-change rays skip the bricks whose change over time cannot beat the change they keep
// (RaycastVariant::skipUnchangingBricks): the bound of a brick (render::brickChangeBounds) in closed
// form, then the automatic scenes of the realistic maps (a monthly climatology, an ocean eddy, a
// regional forecast: largest-change seen from above) drawn with the skip and without, under the
// compositors whose change the bricks bound: the same pixels, the skip taken, and fewer fetches.
#include <filesystem>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "../data/realistic_datasets.h"
#include "render_test_support.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/render/brick_occupancy.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::testing {
namespace {

// A time-step of 9 x 5 x 5 samples, 2 x 1 x 1 bricks: brick 0 holds x 0 .. 4, brick 1 x 4 .. 8.
TimeStep constantStep(float density) {
    static_assert(kBrickSize == 4, "the samples below are placed for bricks of 4 cells");
    TimeStep step;
    RectilinearGrid grid;
    grid.dims = {9, 5, 5};
    step.grid = grid;
    step.density.assign(grid.voxelCount(), density);
    return step;
}

std::size_t sampleIndex(int x, int y, int z) { return std::size_t((z * 5 + y) * 9 + x); }

TEST(BrickChangeBounds, AreTheLargestRangeOverTimeOfTheirSamples) {
    const TimeStep first = constantStep(0.2f);
    TimeStep second = constantStep(0.2f);
    second.density[sampleIndex(6, 2, 2)] = 0.9f;  // inside brick 1 only
    TimeStep third = constantStep(0.2f);
    third.density[sampleIndex(1, 0, 0)] = 0.05f;  // inside brick 0 only
    EXPECT_EQ(brickChangeBounds(std::vector<TimeStep>{first, second, third}),
              (std::vector<float>{0.2f - 0.05f, 0.9f - 0.2f}));
    // A sample on the face between them (x = 4) belongs to both bricks' lookups.
    TimeStep fourth = constantStep(0.2f);
    fourth.density[sampleIndex(4, 3, 1)] = 1.0f;
    EXPECT_EQ(brickChangeBounds(std::vector<TimeStep>{first, fourth}), (std::vector<float>{0.8f, 0.8f}));
}

TEST(BrickChangeBounds, LeaveOutWhatVariesInSpaceAlone) {
    // Densities that rise along x and never change: no change, though each brick spans 0.5.
    TimeStep ramp = constantStep(0.0f);
    for (int z = 0; z < 5; ++z)
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 9; ++x) ramp.density[sampleIndex(x, y, z)] = float(x) / 8.0f;
    EXPECT_EQ(brickChangeBounds(std::vector<TimeStep>{ramp, ramp, ramp}), (std::vector<float>{0.0f, 0.0f}));
    // The same ramp a quarter higher in a second time-step: every sample changes by a quarter.
    TimeStep raised = ramp;
    for (float& density : raised.density) density += 0.25f;
    EXPECT_EQ(brickChangeBounds(std::vector<TimeStep>{ramp, raised}), (std::vector<float>{0.25f, 0.25f}));
}

TEST(BrickChangeBounds, ABrickWithoutDataInAnyTimeStepHasNone) {
    TimeStep first = constantStep(0.5f);
    TimeStep second = constantStep(0.7f);
    for (TimeStep* step : {&first, &second})
        for (int z = 0; z < 5; ++z)
            for (int y = 0; y < 5; ++y)
                for (int x = 5; x < 9; ++x) step->density[sampleIndex(x, y, z)] = missingDensity();
    // Brick 1 still reads the samples at x = 4.
    EXPECT_FLOAT_EQ(brickChangeBounds(std::vector<TimeStep>{first, second})[1], 0.7f - 0.5f);
    for (TimeStep* step : {&first, &second})
        for (int z = 0; z < 5; ++z)
            for (int y = 0; y < 5; ++y) step->density[sampleIndex(4, y, z)] = missingDensity();
    EXPECT_EQ(brickChangeBounds(std::vector<TimeStep>{first, second})[1], -1.0f);
}

TEST(BrickChangeBounds, RefuseGridsThatDiffer) {
    TimeStep other;
    RectilinearGrid grid;
    grid.dims = {5, 5, 5};
    other.grid = grid;
    other.density.assign(grid.voxelCount(), 0.5f);
    EXPECT_THROW(brickChangeBounds(std::vector<TimeStep>{constantStep(0.5f), other}), std::invalid_argument);
}

struct Frame {
    Image image;
    RaycastVariant variant;
    RaycastStatistics statistics;
};

struct MapCase {
    const char* name;
    std::function<void(const std::filesystem::path&)> write;
    const char* compositor;  // empty: the automatic scene's own
    double fetchShare;       // the most of the fetches without the skip that it may take
};

Frame drawMap(const MapCase& map, bool skip) {
    const auto folder = std::filesystem::temp_directory_path() / ("tstyles_skip_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const auto file = folder / (std::string(map.name) + ".nc");
    map.write(file);
    Series raw = openSeries(file, ReadOptions{});
    std::filesystem::remove_all(folder);
    Scene scene = automaticScene(raw, file).scene;
    EXPECT_EQ(toString(scene.rayMode), "largest-change") << map.name << ": the automatic scene of a map";
    if (*map.compositor) scene.compositor = *temporalCompositorFromString(map.compositor);
    scene.width = scene.height = 160;
    const SceneOnSeries fitted = fitSceneToSeries(scene, std::move(raw));
    Renderer& renderer = testRenderer();
    renderer.setSeries(fitted.series);
    FrameOptions options;
    options.size = {scene.width, scene.height};
    options.collectStatistics = true;
    options.skipUnchangingBricks = skip;
    renderer.draw(fitted.scene,
                  resolveView(fitted.scene.camera, fitted.framed, fitted.series.worldBounds(), scene.width, scene.height),
                  options);
    return {renderer.readFrame(), renderer.lastVariant(), renderer.lastStatistics()};
}

class UnchangingBrickSkip : public ::testing::TestWithParam<MapCase> {};

// Measured on llvmpipe at 160 x 160 (7 December): every pixel the same with and without the skip;
// the fetches down to 0.225 of those without it on the climatology (0.314 as a standard deviation,
// which is at most half the range it is bounded by), 0.089 on the eddy, whose change sits in its
// top layers. The forecast's largest change is at the ground, below layers that change less: a ray
// from above keeps ever larger changes and skips nothing (1.0). Each share may be at most a third
// higher; a bound that let nothing be skipped would give 1.
TEST_P(UnchangingBrickSkip, TakesTheSameSamplesThatCanChangeThePicture) {
    const MapCase& map = GetParam();
    const Frame skipped = drawMap(map, true);
    const Frame whole = drawMap(map, false);
    EXPECT_TRUE(skipped.variant.skipUnchangingBricks) << "the skip was not taken";
    EXPECT_EQ(skipped.variant.walk, TimeStepWalk::PackedGroups);
    EXPECT_FALSE(whole.variant.skipUnchangingBricks);
    ASSERT_EQ(skipped.image.rgba.size(), whole.image.rgba.size());
    int differing = 0;
    for (std::size_t i = 0; i < whole.image.rgba.size(); ++i)
        if (skipped.image.rgba[i] != whole.image.rgba[i]) ++differing;
    EXPECT_EQ(differing, 0) << "pixel values that differ";
    EXPECT_EQ(skipped.statistics.rays, whole.statistics.rays);
    const double share = double(skipped.statistics.fetches) / double(whole.statistics.fetches);
    std::cout << map.name << " " << (*map.compositor ? map.compositor : "(automatic)") << ": fetches "
              << skipped.statistics.fetches << " of " << whole.statistics.fetches << " (" << share << ")\n";
    EXPECT_LE(share, map.fetchShare);
}

INSTANTIATE_TEST_SUITE_P(
    RealisticMaps, UnchangingBrickSkip,
    ::testing::Values(MapCase{"climatology", testdata::writeOceanClimatology, "", 0.3},
                      MapCase{"climatology_max_change", testdata::writeOceanClimatology, "temporal-max-change", 0.3},
                      MapCase{"climatology_std_dev", testdata::writeOceanClimatology, "temporal-std-dev", 0.42},
                      MapCase{"eddy", testdata::writeOceanEddy, "", 0.12},
                      MapCase{"forecast", testdata::writeRegionalForecast, "", 1.0}),
    [](const auto& parameter) { return std::string(parameter.param.name); });

}  // namespace
}  // namespace tstyles::testing
