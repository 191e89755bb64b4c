// The automatic scene's ray step (tstyles/scene/automatic_step.h) against the exact one, half the
// finest spacing: on data with uneven levels, the bundled hurricane (25 uneven levels, composited:
// a whole typical cell) and the realistic ocean eddy (12 depth levels, a few metres thin at the
// surface; a map, drawn as the largest change along each column: half a cell); on even grids
// composited at a whole cell, the bundled super-ellipsoid and a CT phantom with noise; and on the
// sonar's beam grids, at 256 x 256 through the readers. The faster step is asserted taken (the
// scene's step is set, and coarser than the default); the pictures agree within what was measured.
#include <filesystem>
#include <iostream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "../data/realistic_datasets.h"
#include "render_test_support.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/image/image_comparison.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::testing {
namespace {

struct StepPair {
    double step = 0.0;
    double exactStep = 0.0;
    ImageDifference difference;
};

StepPair renderBothSteps(const std::filesystem::path& file) {
    Series raw = openSeries(file, ReadOptions{});
    Scene scene = automaticScene(raw, file).scene;
    scene.width = scene.height = 256;
    const SceneOnSeries fitted = fitSceneToSeries(scene, std::move(raw));
    StepPair pair;
    EXPECT_TRUE(fitted.scene.raycast.step.has_value()) << "the automatic step was not taken";
    pair.step = fitted.scene.raycast.step.value_or(0.0);
    pair.exactStep = 0.5 * fitted.series.finestSpacing();
    Renderer& renderer = testRenderer();
    renderer.setSeries(fitted.series);
    // One variable: both frames take their gradients with six fetches (the second styled frame of a
    // series would otherwise read the gradient atlas).
    auto draw = [&](const Scene& drawn) {
        FrameOptions options;
        options.size = {drawn.width, drawn.height};
        options.precomputedGradients = false;
        renderer.draw(drawn, resolveView(drawn.camera, fitted.framed, fitted.series.worldBounds(), drawn.width,
                                         drawn.height),
                      options);
        return renderer.readFrame();
    };
    const Image faster = draw(fitted.scene);
    Scene exact = fitted.scene;
    exact.raycast.step.reset();
    const Image exactImage = draw(exact);
    pair.difference = compareImages(exactImage, faster, 1);
    std::cout << file.filename().string() << ": step " << pair.step << " against " << pair.exactStep << ": max "
              << pair.difference.maxDelta << "/255, mean " << pair.difference.meanDelta << "/255, SSIM "
              << pair.difference.ssim << ", " << pair.difference.failingFraction << " of the pixels differ\n";
    return pair;
}

// Measured on llvmpipe (EGL and OSMesa alike, 7 December): a whole cell, step 0.0127 against
// 0.00417; max 23/255, mean 0.194/255, SSIM 0.99925, 8.3 % of the pixels differ by more than 1/255.
// (Half a cell, 0.00634, gave max 13/255, mean 0.110/255, SSIM 0.99975.)
TEST(AutomaticStep, TheHurricanesLevelsGiveACoarserStepAndTheSamePicture) {
    const StepPair pair =
        renderBothSteps(std::filesystem::path(TSTYLES_SOURCE_DIR) / "data/hurricane/series.json");
    EXPECT_GT(pair.step, 2.8 * pair.exactStep);
    EXPECT_LE(pair.difference.maxDelta, 32);
    EXPECT_LE(pair.difference.meanDelta, 0.3);
    EXPECT_GE(pair.difference.ssim, 0.998);
}

// Even grids composite at one spacing, twice the exact step. Measured on llvmpipe (7 December):
// the super-ellipsoid max 12/255, mean 0.0127/255, SSIM 0.999975, 0.43 % of the pixels beyond
// 1/255 (on its bodies' rims); the CT phantom (a noisy cylinder and ellipsoid in air) max 46/255,
// mean 0.137/255, SSIM 0.9938, 3.2 % of the pixels, the speckle of its noise's time colours.
TEST(AutomaticStep, EvenGridsCompositeAtOneSpacingAndTheSamePicture) {
    const StepPair bodies =
        renderBothSteps(std::filesystem::path(TSTYLES_SOURCE_DIR) / "data/superellipsoid/series.json");
    EXPECT_NEAR(bodies.step, 2.0 * bodies.exactStep, 1e-9);
    EXPECT_LE(bodies.difference.maxDelta, 18);
    EXPECT_LE(bodies.difference.meanDelta, 0.025);
    EXPECT_GE(bodies.difference.ssim, 0.9999);
    const auto folder = std::filesystem::temp_directory_path() / ("tstyles_step_ct_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    testdata::writeCtPhantom(folder / "ct-phantom.nii");
    const StepPair ct = renderBothSteps(folder / "ct-phantom.nii");
    std::filesystem::remove_all(folder);
    EXPECT_NEAR(ct.step, 2.0 * ct.exactStep, 1e-6);
    EXPECT_LE(ct.difference.maxDelta, 64);
    EXPECT_LE(ct.difference.failingFraction, 0.045);
    EXPECT_LE(ct.difference.meanDelta, 0.2);
    EXPECT_GE(ct.difference.ssim, 0.99);
}

// Measured: step 0.0764 against 0.00855 (8.9 times). The map is the largest change along each
// column: 0.24 % of the pixels differ, all on the eddies' rims, where the kept sample turns from
// a changing place (a time colour) to an unchanged one (grey) between the two steps (max 155/255
// there); mean 0.166/255, SSIM 0.9914. (Composited, before the map became the largest change: max
// 46/255, mean 0.096/255, SSIM 0.99867.)
TEST(AutomaticStep, TheOceansThinSurfaceLevelsNoLongerSetTheStep) {
    const auto folder = std::filesystem::temp_directory_path() / ("tstyles_step_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    testdata::writeOceanEddy(folder / "ocean-eddy.nc");
    const StepPair pair = renderBothSteps(folder / "ocean-eddy.nc");
    std::filesystem::remove_all(folder);
    EXPECT_GT(pair.step, 4.0 * pair.exactStep);
    EXPECT_LE(pair.difference.failingFraction, 0.004);
    EXPECT_LE(pair.difference.meanDelta, 0.25);
    EXPECT_GE(pair.difference.ssim, 0.99);
}

// The sonar's beam grids: one range cell, 0.0895, against half of it. Measured on llvmpipe at
// 256 x 256 (7 December): a speckle in the seabed's echoes, max 16/255, 4.1 % of the pixels differ,
// mean 0.117/255, SSIM 0.9968.
TEST(AutomaticStep, TheSonarsFansTakeOneRangeCellAndTheSamePicture) {
    const StepPair pair = renderBothSteps(std::filesystem::path(TSTYLES_SOURCE_DIR) / "data/sonar/series.json");
    EXPECT_NEAR(pair.step, 2.0 * pair.exactStep, 1e-6);
    EXPECT_LE(pair.difference.maxDelta, 24);
    EXPECT_LE(pair.difference.meanDelta, 0.2);
    EXPECT_GE(pair.difference.ssim, 0.995);
}

}  // namespace
}  // namespace tstyles::testing
