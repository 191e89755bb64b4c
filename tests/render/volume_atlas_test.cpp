// The volume atlas: packing many time-steps into one 3D texture, and rendering them in one pass.
#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/core/errors.h"
#include "tstyles/render/atlas_layout.h"

namespace tstyles::testing {
namespace {

TEST(AtlasLayout, SixtyFourTimeStepsOf64CubedFormA256CubedAtlas) {
    const AtlasLayout layout = planAtlas(std::vector<glm::ivec3>(64, glm::ivec3(64)), 2048);
    EXPECT_EQ(layout.size, glm::ivec3(256));
    ASSERT_EQ(layout.brickOrigins.size(), 64u);
    EXPECT_EQ(layout.brickOrigins[0], glm::ivec3(0));
    EXPECT_EQ(layout.brickOrigins[63], glm::ivec3(192));
}

// No two bricks share a texel, and every brick lies inside the atlas.
void expectDisjointInside(const AtlasLayout& layout, const std::vector<glm::ivec3>& dims) {
    ASSERT_EQ(layout.brickOrigins.size(), dims.size());
    for (std::size_t i = 0; i < dims.size(); ++i) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(layout.brickOrigins[i], glm::ivec3(0))));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(layout.brickOrigins[i] + dims[i], layout.size))) << "brick " << i;
        for (std::size_t j = i + 1; j < dims.size(); ++j) {
            const glm::ivec3 lower = glm::max(layout.brickOrigins[i], layout.brickOrigins[j]);
            const glm::ivec3 upper = glm::min(layout.brickOrigins[i] + dims[i], layout.brickOrigins[j] + dims[j]);
            EXPECT_FALSE(glm::all(glm::lessThan(lower, upper))) << "bricks " << i << " and " << j << " overlap";
        }
    }
}

// Bricks of different sizes stack in columns where that takes fewer texels than equal cells of
// the largest brick (three cells of 30 x 20 x 8, 14 400 texels): here one column along x of
// (10 + 30 + 8) x 20 x 8, 7 680 texels; along z it would be 30 x 20 x 18, 10 800.
TEST(AtlasLayout, BricksOfDifferentSizesStackInColumns) {
    const std::vector<glm::ivec3> dims = {{10, 20, 5}, {30, 4, 5}, {8, 8, 8}};
    const AtlasLayout layout = planAtlas(dims, 64);
    EXPECT_EQ(layout.size, glm::ivec3(48, 20, 8));
    expectDisjointInside(layout, dims);
}

// A distributed block of a partial-overlap series: five time-steps kept whole, five cut to one
// cell. Equal cells would take ten 64^3 cells; columns take about half.
TEST(AtlasLayout, ABlockWithCutTimeStepsTakesAboutItsOwnSize) {
    std::vector<glm::ivec3> dims;
    for (int step = 0; step < 10; ++step) dims.push_back(step % 2 == 0 ? glm::ivec3(64) : glm::ivec3(2));
    const AtlasLayout layout = planAtlas(dims, 2048);
    EXPECT_LE(layout.texelCount(), std::size_t(5 * 64 * 64 * 64 + 5 * 64 * 64 * 2));
    expectDisjointInside(layout, dims);
}

// Bricks of one size keep the equal cells (the layout of every series but a block's).
TEST(AtlasLayout, BricksOfOneSizeKeepEqualCells) {
    const AtlasLayout layout = planAtlas(std::vector<glm::ivec3>(10, glm::ivec3(64, 32, 16)), 2048);
    EXPECT_EQ(layout.cellSize, glm::ivec3(64, 32, 16));
    EXPECT_EQ(layout.texelCount(), std::size_t(10 * 64 * 32 * 16));
}

// Columns stay within the texture's side, and fit where equal cells do not: 40 bricks of 16 x 16
// x 4, 16 or 28 in a 64 cube, which holds only 32 cells of 16 x 16 x 28.
TEST(AtlasLayout, ColumnsFitWhereEqualCellsDoNot) {
    std::vector<glm::ivec3> dims;
    for (int brick = 0; brick < 40; ++brick) dims.push_back(glm::ivec3(16, 16, 4 + brick % 3 * 12));
    const AtlasLayout layout = planAtlas(dims, 64);
    EXPECT_TRUE(glm::all(glm::lessThanEqual(layout.size, glm::ivec3(64))));
    expectDisjointInside(layout, dims);
}

TEST(AtlasLayout, TooManyTimeStepsForOneTextureIsAnInputError) {
    EXPECT_THROW(planAtlas(std::vector<glm::ivec3>(9, glm::ivec3(32)), 64), InputError);
    EXPECT_THROW(planAtlas({glm::ivec3(65, 8, 8)}, 64), InputError);
}

TEST(VolumeAtlasRender, SixtyFourTimeStepsRenderInOnePass) {
    // 64 boxes in an 8x8 grid of the xy-plane; time-step i is coloured by its index.
    std::vector<BoxSpec> boxes;
    for (int i = 0; i < 64; ++i) boxes.push_back(constantBox({double(i % 8), double(i / 8), 0.0}, 1.0f));
    const Series series = makeSeries(boxes);
    const glm::dvec2 centre(3.85, 3.85);
    const double viewHeight = 8.0;
    Scene scene = orthographicSceneLookingDownZ(centre, viewHeight, 128);
    scene.stf.curve = constantFunction({1, 1, 1}, 1.0);
    scene.indexTstf.curve.opacity = {{0.0, 1.0}};
    scene.indexTstf.curve.color = {{0.0, {0, 0, 0}}, {63.0, {1, 1, 1}}};  // grey level = index / 63
    scene.finalMode = FinalMode::Tstf;
    const Image image = renderSeries(series, scene);
    for (int i : {0, 9, 27, 63}) {
        const glm::ivec2 pixel = pixelOf({i % 8 + 0.35, i / 8 + 0.35}, centre, viewHeight, 128);
        EXPECT_NEAR(image.at(pixel.x, pixel.y).r, i / 63.0f, 2e-3f) << "time-step " << i;
        EXPECT_NEAR(image.at(pixel.x, pixel.y).a, 1.0f, 1e-6f) << "time-step " << i;
    }
}

}  // namespace
}  // namespace tstyles::testing
