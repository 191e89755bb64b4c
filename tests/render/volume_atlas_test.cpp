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

TEST(AtlasLayout, BricksOfDifferentSizesShareTheLargestCell) {
    const AtlasLayout layout = planAtlas({{10, 20, 5}, {30, 4, 5}, {8, 8, 8}}, 64);
    EXPECT_EQ(layout.cellSize, glm::ivec3(30, 20, 8));
    for (std::size_t i = 0; i < layout.brickOrigins.size(); ++i)
        for (std::size_t j = i + 1; j < layout.brickOrigins.size(); ++j)
            EXPECT_NE(layout.brickOrigins[i], layout.brickOrigins[j]);
    EXPECT_LE(layout.size.x, 64);
    EXPECT_LE(layout.size.y, 64);
    EXPECT_LE(layout.size.z, 64);
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
