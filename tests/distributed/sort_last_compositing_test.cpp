// Sort-last compositing without MPI: the spans of the rounds tile the frame, and slabs are merged
// in the order each pixel's ray meets them.
#include "tstyles/distributed/sort_last_compositing.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace tstyles {
namespace {

TEST(SortLastCompositing, FinalSpansTileTheFrame) {
    const Bounds world{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
    for (int count = 1; count <= 12; ++count) {
        const BlockDecomposition blocks(world, count);
        const std::size_t pixels = 97 * 31;
        std::vector<int> owners(pixels, 0);
        for (int rank = 0; rank < count; ++rank) {
            const PixelSpan span = finalSpan(blocks, rank, pixels);
            for (std::size_t pixel = span.begin; pixel < span.end; ++pixel) ++owners[pixel];
        }
        for (std::size_t pixel = 0; pixel < pixels; ++pixel) ASSERT_EQ(owners[pixel], 1) << count << " processes";
    }
}

TEST(SortLastCompositing, OverIsPremultipliedFrontToBack) {
    const glm::vec4 result = over({0.25f, 0.0f, 0.0f, 0.5f}, {0.0f, 0.5f, 0.0f, 1.0f});
    EXPECT_FLOAT_EQ(result.r, 0.25f);
    EXPECT_FLOAT_EQ(result.g, 0.25f);
    EXPECT_FLOAT_EQ(result.a, 1.0f);
}

// An orthographic camera looking along -x (from +x): every ray runs toward -x, so the slab at the
// upper x end is in front.
glm::dmat4 lookingAlongMinusX() {
    const glm::dmat4 view = glm::lookAt(glm::dvec3(5.0, 0.5, 0.5), glm::dvec3(0.0, 0.5, 0.5), glm::dvec3(0.0, 1.0, 0.0));
    const glm::dmat4 projection = glm::ortho(-1.0, 1.0, -1.0, 1.0, 0.1, 20.0);
    return glm::inverse(projection * view);
}

TEST(SortLastCompositing, SlabsMergeInTheOrderTheRayMeetsThem) {
    const PixelRays rays(lookingAlongMinusX(), {4, 4});
    EXPECT_LT(rays.direction(5).x, 0.0);
    // Slab 0 (lower x) red and half transparent, slab 1 (upper x, in front) green and half transparent.
    const std::vector<float> lower(16 * 4, 0.0f);
    std::vector<float> red(16 * 4), green(16 * 4);
    for (std::size_t pixel = 0; pixel < 16; ++pixel) {
        red[pixel * 4 + 0] = 0.5f;
        red[pixel * 4 + 3] = 0.5f;
        green[pixel * 4 + 1] = 0.5f;
        green[pixel * 4 + 3] = 0.5f;
    }
    std::vector<float> result(16 * 4);
    compositeSlabs({red.data(), green.data()}, {0, 16}, 0, rays, result.data());
    // Green in front: green 0.5, red 0.5 * 0.5, opacity 0.75.
    EXPECT_FLOAT_EQ(result[1], 0.5f);
    EXPECT_FLOAT_EQ(result[0], 0.25f);
    EXPECT_FLOAT_EQ(result[3], 0.75f);
    // Cut along y instead, the rays run across the slabs (direction 0 along y): digit order.
    compositeSlabs({red.data(), green.data()}, {0, 16}, 1, rays, result.data());
    EXPECT_FLOAT_EQ(result[0], 0.5f);
    EXPECT_FLOAT_EQ(result[1], 0.25f);
}

TEST(SortLastCompositing, EntryOrderReferenceAgreesWithTheSlabOrder) {
    const Bounds world{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
    const BlockDecomposition blocks(world, 2);  // x < 0.5 and x > 0.5
    Image lowerFrame(4, 4), upperFrame(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            lowerFrame.set(x, y, {0.5f, 0.0f, 0.0f, 0.5f});
            upperFrame.set(x, y, {0.0f, 0.5f, 0.0f, 0.5f});
        }
    const Image result = compositeInEntryOrder({lowerFrame, upperFrame}, blocks, lookingAlongMinusX());
    EXPECT_FLOAT_EQ(result.at(1, 1).g, 0.5f);
    EXPECT_FLOAT_EQ(result.at(1, 1).r, 0.25f);
}

}  // namespace
}  // namespace tstyles
