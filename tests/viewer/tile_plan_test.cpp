// Progressive refinement's tiles: they cover the frame exactly once, and a cropped projection
// sends every pixel centre through the same ray as the full projection.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "viewer/tile_plan.h"

namespace {

using namespace tstyles::viewer;

TEST(TilePlan, TilesCoverTheFrameExactlyOnce) {
    const glm::ivec2 frame{973, 493};
    for (int divisor : {1, 2, 3, 7, 16}) {
        std::vector<int> covered(std::size_t(frame.x) * std::size_t(frame.y), 0);
        for (const PixelWindow& tile : planTiles(frame, divisor)) {
            EXPECT_EQ(tile.size, tileSizeFor(frame, divisor));
            for (int y = tile.offset.y; y < std::min(tile.offset.y + tile.size.y, frame.y); ++y)
                for (int x = tile.offset.x; x < std::min(tile.offset.x + tile.size.x, frame.x); ++x)
                    ++covered[std::size_t(y) * std::size_t(frame.x) + std::size_t(x)];
        }
        for (const int count : covered) ASSERT_EQ(count, 1) << "divisor " << divisor;
    }
}

TEST(TilePlan, TheCentreComesFirst) {
    const std::vector<PixelWindow> tiles = planTiles({300, 300}, 3);
    ASSERT_EQ(tiles.size(), 9u);
    EXPECT_EQ(tiles.front().offset, glm::ivec2(100, 100));
}

TEST(TilePlan, CroppedProjectionKeepsEveryPixelsRay) {
    const glm::dmat4 projection = glm::perspective(0.6, 973.0 / 493.0, 0.1, 20.0);
    const glm::ivec2 frame{973, 493};
    const PixelWindow tile{{325, 165}, {325, 165}};
    const glm::dmat4 cropped = cropProjection(projection, frame, tile);
    for (const glm::ivec2 pixel : {glm::ivec2(0, 0), glm::ivec2(17, 99), glm::ivec2(324, 164)}) {
        // The same pixel centre in the frame's and in the tile's normalized device coordinates.
        const glm::dvec2 frameNdc = (glm::dvec2(tile.offset + pixel) + 0.5) / glm::dvec2(frame) * 2.0 - 1.0;
        const glm::dvec2 tileNdc = (glm::dvec2(pixel) + 0.5) / glm::dvec2(tile.size) * 2.0 - 1.0;
        for (const double depth : {-1.0, 1.0}) {
            const glm::dvec4 full = glm::inverse(projection) * glm::dvec4(frameNdc, depth, 1.0);
            const glm::dvec4 crop = glm::inverse(cropped) * glm::dvec4(tileNdc, depth, 1.0);
            EXPECT_NEAR(glm::distance(glm::dvec3(full) / full.w, glm::dvec3(crop) / crop.w), 0.0, 1e-9);
        }
    }
}

TEST(TilePlan, ACroppedViewsPixelsAreTheFramesPixels) {
    tstyles::View view;
    view.fovDeg = 30.0;
    const glm::ivec2 frame{900, 600};
    const tstyles::View tile = cropView(view, frame, {{300, 200}, {300, 200}});
    // The renderer sizes a pixel as 2 d tan(fov / 2) / height: the same for the tile (200 pixels
    // high) as for the frame (600).
    EXPECT_NEAR(std::tan(glm::radians(tile.fovDeg) / 2.0) / 200.0, std::tan(glm::radians(30.0) / 2.0) / 600.0, 1e-15);
    // A preview of the whole frame at a third of the size has pixels three times as large.
    const tstyles::View preview = cropView(view, frame, {{0, 0}, frame});
    EXPECT_NEAR(preview.fovDeg, 30.0, 1e-12);
}

TEST(TilePlan, PreviewDivisorFollowsTheRenderTime) {
    // Four times too slow: twice the divisor (pixels go with its square).
    EXPECT_EQ(previewDivisorFor(180.0, 2, 45.0, 16), 4);
    // A bit off either way: keep it, so the preview does not flicker between sizes.
    EXPECT_EQ(previewDivisorFor(50.0, 3, 45.0, 16), 3);
    EXPECT_EQ(previewDivisorFor(30.0, 3, 45.0, 16), 3);
    // Far too fast: smaller divisor, never below 1 or above the limit.
    EXPECT_EQ(previewDivisorFor(1.0, 8, 45.0, 16), 2);
    EXPECT_EQ(previewDivisorFor(0.01, 2, 45.0, 16), 1);
    EXPECT_EQ(previewDivisorFor(1e6, 2, 45.0, 16), 16);
}

TEST(TilePlan, CoarsePreviewsTakeLongerSteps) {
    EXPECT_EQ(previewStepScaleFor(1), kPreviewStepScale);
    EXPECT_EQ(previewStepScaleFor(4), kPreviewStepScale);
    EXPECT_EQ(previewStepScaleFor(5), 2.5f);
    EXPECT_EQ(previewStepScaleFor(16), 8.0f);
}

}  // namespace
