// Missing values and uneven axes, rendered and compared with closed-form values: a voxel without
// data is transparent and left out of every temporal compositor; an uneven axis puts a density
// step where its node list says.
#include <cmath>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/render/brick_occupancy.h"
#include "tstyles/render/density_texels.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 64;
constexpr double kViewHeight = 2.0;
constexpr double kBoxWidth = kConstantBoxWidth;
// As in analytic_render_test.cpp: 16-bit densities, 1024-entry tables, float arithmetic.
constexpr float kTolerance = 2e-3f;

void expectPixel(const Image& image, glm::ivec2 pixel, glm::vec4 expected, const char* what) {
    const glm::vec4 actual = image.at(pixel.x, pixel.y);
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(actual[c], expected[c], kTolerance)
            << what << " at pixel (" << pixel.x << ", " << pixel.y << ") channel " << c;
}

// A constant box whose samples with x < 4 (world x < 0.35 from its origin) have no data.
BoxSpec boxMissingOnTheLeft(float density) {
    BoxSpec box = constantBox({0, 0, 0}, density);
    box.density = [density](glm::ivec3 voxel) { return voxel.x < 4 ? missingDensity() : density; };
    return box;
}

// Where the left half of a box is missing (nodes x = 0..3) and where it has data (x = 5..7); the
// validity boundary, between nodes 3 and 4, is kept away from.
const glm::dvec2 kCentre(0.35, 0.35);
const glm::dvec2 kInsideTheGap(0.1, 0.35);
const glm::dvec2 kWithData(0.6, 0.35);

TEST(MissingValuesRender, AverageLeavesOutTheTimeStepWithoutData) {
    const float densities[3] = {0.2f, 0.5f, 0.8f};
    const Series series = makeSeries({constantBox({0, 0, 0}, densities[0]), boxMissingOnTheLeft(densities[1]),
                                      constantBox({0, 0, 0}, densities[2])});
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    // Density 0 is not transparent here, so a missing value read as 0 would show.
    scene.stf.curve.opacity = {{0.0, 0.05}, {1.0, 0.15}};
    scene.stf.curve.color = {{0.0, {0, 0, 1}}, {1.0, {1, 0, 0}}};
    scene.compositor = compositorNamed("temporal-average");
    scene.finalMode = FinalMode::Stf;
    // The average over the given time-steps: opacities averaged, colours weighted by opacity.
    const auto averageOf = [](std::initializer_list<float> present) {
        double opacitySum = 0.0;
        glm::dvec3 weightedColor(0.0);
        for (float density : present) {
            const double opacity = 0.05 + 0.1 * density;
            opacitySum += opacity;
            weightedColor += opacity * glm::dvec3(density, 0.0, 1.0 - density);
        }
        const double alpha = slabOpacity(opacitySum / double(present.size()), kBoxWidth);
        return glm::vec4(glm::vec3(weightedColor / opacitySum * alpha), float(alpha));
    };
    const Image image = renderSeries(series, scene);
    expectPixel(image, pixelOf(kInsideTheGap, kCentre, kViewHeight, kSize), averageOf({0.2f, 0.8f}),
                "average of steps 0 and 2 where step 1 has no data");
    expectPixel(image, pixelOf(kWithData, kCentre, kViewHeight, kSize), averageOf({0.2f, 0.5f, 0.8f}),
                "average of all three");
}

TEST(MissingValuesRender, MipPicksTheOtherTimeStepWhereTheLargerHasNoData) {
    // Opacity falls with density: step 1 (density 0.2, opacity 0.8) is the larger one; a missing
    // value read as density 0 would be larger still (opacity 1) and win.
    const Series series = makeSeries({constantBox({0, 0, 0}, 0.7f), boxMissingOnTheLeft(0.2f)});
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 1.0}, {1.0, 0.0}};
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {1, 0, 0}}, {1.0, {0, 1, 0}}};
    scene.compositor = compositorNamed("temporal-mip");
    scene.finalMode = FinalMode::Tstf;
    const Image image = renderSeries(series, scene);
    expectPixel(image, pixelOf(kInsideTheGap, kCentre, kViewHeight, kSize), {1, 0, 0, 1}, "step 0 where step 1 is missing");
    expectPixel(image, pixelOf(kWithData, kCentre, kViewHeight, kSize), {0, 1, 0, 1}, "step 1, the larger");
}

TEST(MissingValuesRender, MaxDensityChangeIsOnlyBetweenValidValues) {
    const float a = 0.3f;
    const float b = 0.9f;
    const Series series = makeSeries({constantBox({0, 0, 0}, a), boxMissingOnTheLeft(b)});
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 1.0}};
    scene.stf.curve.color = {{0.0, {0, 0, 0}}, {1.0, {1, 1, 1}}};
    scene.gradientTstf.curve.opacity = {{0.0, 1.0}};
    scene.gradientTstf.curve.color = {{0.0, {0, 1, 0}}, {1.0, {1, 0.5, 0}}};
    scene.compositor = compositorNamed("temporal-max-change");
    scene.finalMode = FinalMode::Tstf;
    const Image image = renderSeries(series, scene);
    const double change = b - a;
    expectPixel(image, pixelOf(kWithData, kCentre, kViewHeight, kSize),
                {float(change), float(1.0 - 0.5 * change), 0.0f, 1.0f}, "change between two valid values");
    // One valid value only: no change is defined and the STF of step 0 shows (not a change of 0.3).
    expectPixel(image, pixelOf(kInsideTheGap, kCentre, kViewHeight, kSize), {a, a, a, 1}, "STF of the valid step");
}

TEST(MissingValuesRender, AFullyMissingRegionIsTransparent) {
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.background = {0.25, 0.5, 0.75, 1.0};
    scene.stf.curve = constantFunction({1, 1, 1}, 1.0);  // opaque white wherever there is data
    scene.finalMode = FinalMode::Stf;
    for (auto compositor : {compositorNamed("temporal-mip"), compositorNamed("temporal-average"),
                            compositorNamed("temporal-max-change")}) {
        scene.compositor = compositor;
        for (std::size_t steps : {1u, 2u}) {
            std::vector<BoxSpec> boxes(steps, boxMissingOnTheLeft(0.5f));
            const Image image = renderSeries(makeSeries(boxes), scene);
            expectPixel(image, pixelOf(kInsideTheGap, kCentre, kViewHeight, kSize), {0.25f, 0.5f, 0.75f, 1.0f},
                        "background through the missing region");
            expectPixel(image, pixelOf(kWithData, kCentre, kViewHeight, kSize), {1, 1, 1, 1}, "the data");
        }
    }
}

// A box whose density steps from 0 to 1 between z nodes 3 and 4, with z nodes at
// 0, 0.02, 0.04, 0.06, 0.5, 0.6, 0.65, 0.7: density 0.5 (the STF's step) is at z = 0.28, where an
// evenly spaced axis of the same extent would put it at z = 0.35.
TEST(UnevenAxesRender, ADensityStepLandsAtTheRowItsNodesPredict) {
    BoxSpec box = constantBox({0, 0, 0}, 0.0f);
    box.density = [](glm::ivec3 voxel) { return voxel.z >= 4 ? 1.0f : 0.0f; };
    Series series = makeSeries({box});
    std::get<RectilinearGrid>(series.steps[0].grid).axisPositions[2] = {0, 0.02, 0.04, 0.06, 0.5, 0.6, 0.65, 0.7};
    const double boundary = 0.28;

    // Looking down -x with z up: image columns follow world y, rows world z.
    constexpr int size = 128;
    constexpr double viewHeight = 1.0;
    const glm::dvec2 centre(0.35, 0.35);  // (y, z)
    Scene scene;
    scene.camera.pose = LookAtCamera{{10.0, centre.x, centre.y}, {0.0, centre.x, centre.y}, {0.0, 0.0, 1.0}};
    scene.camera.projection = Projection::Orthographic;
    scene.camera.fovDeg = glm::degrees(2.0 * std::atan(viewHeight / 20.0));
    scene.width = size;
    scene.height = size;
    scene.background = glm::dvec4(0.0);
    scene.stf.curve.opacity = {{0.5, 0.0}, {0.5, 1.0}};
    scene.stf.curve.color = {{0.0, {1, 1, 1}}};
    scene.finalMode = FinalMode::Stf;
    const Image image = renderSeries(series, scene);

    // The first row from the top that is no longer opaque, in the column through y = 0.35.
    const int column = pixelOf(centre, centre, viewHeight, size).x;
    int firstClear = -1;
    for (int row = pixelOf({0.35, 0.69}, centre, viewHeight, size).y; row < size; ++row) {
        if (image.at(column, row).a < 0.5f) {
            firstClear = row;
            break;
        }
    }
    // Pixel centres at or above the boundary are opaque: the first clear row is the one whose
    // centre lies just below z = 0.28.
    const double rowOfBoundary = (0.5 - (boundary - centre.y) / viewHeight) * size;  // 89.6
    EXPECT_EQ(firstClear, int(std::ceil(rowOfBoundary - 0.5))) << "uneven z: boundary row";
    const int evenRow = int(std::ceil((0.5 - (0.35 - centre.y) / viewHeight) * size - 0.5));
    EXPECT_GE(firstClear - evenRow, 8) << "an even axis would put the boundary 9 rows higher";
    // Well above and below the boundary: opaque white and clear.
    expectPixel(image, pixelOf({0.35, 0.4}, centre, viewHeight, size), {1, 1, 1, 1}, "above the step");
    expectPixel(image, pixelOf({0.35, 0.2}, centre, viewHeight, size), {0, 0, 0, 0}, "below the step");
}

}  // namespace
}  // namespace tstyles::testing

namespace tstyles::testing {
namespace {

// Empty-space skipping must not count missing voxels as densities: a brick's range is that of
// its valid samples, and a brick without any is never visible.
TEST(MissingValuesOccupancy, BrickRangesIgnoreMissingVoxels) {
    constexpr int k = kBrickSize;
    TimeStep step;
    RectilinearGrid grid;
    grid.dims = {2 * k + 1, k + 1, k + 1};  // two bricks along x: samples 0..k and k..2k
    grid.spacing = glm::dvec3(0.1);
    step.grid = grid;
    step.density.assign(grid.voxelCount(), 0.25f);
    const std::size_t row = std::size_t(grid.dims.x);
    // The second brick has no data, its first face (x = k) included.
    for (std::size_t i = 0; i < step.density.size(); ++i)
        if (i % row >= std::size_t(k)) step.density[i] = missingDensity();
    step.density[0] = 0.75f;
    const BrickGrid bricks = computeBrickGrid(step);
    ASSERT_EQ(bricks.minMax.size(), 2u);
    EXPECT_EQ(bricks.minMax[0].first, 0.25f);
    EXPECT_EQ(bricks.minMax[0].second, 0.75f);
    EXPECT_GT(bricks.minMax[1].first, bricks.minMax[1].second) << "no valid sample: empty range";

    // An STF that is opaque everywhere, even at density 0: the brick without data stays invisible.
    const std::vector<glm::vec4> opaque(1024, glm::vec4(1.0f));
    const std::vector<std::uint8_t> visible = brickVisibility(bricks, OpacityRangeMaximum(opaque));
    EXPECT_EQ(visible[0], 255);
    EXPECT_EQ(visible[1], 0);
}

TEST(MissingValuesOccupancy, DensityTexelsArePremultipliedByValidity) {
    TimeStep step;
    step.density = {0.5f, missingDensity(), 1.0f};
    EXPECT_EQ(densityTexels(step, false), (std::vector<std::uint16_t>{32768, 0, 65535}));
    EXPECT_EQ(densityTexels(step, true), (std::vector<std::uint16_t>{32768, 65535, 0, 0, 65535, 65535}));
}

}  // namespace
}  // namespace tstyles::testing
