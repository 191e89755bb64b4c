// The k-d split of the world for sort-last rendering: blocks tile the bounds, and the digits name
// the groups of each compositing round.
#include "tstyles/distributed/block_decomposition.h"

#include <vector>

#include <gtest/gtest.h>

namespace tstyles {
namespace {

double volume(const Bounds& box) {
    const glm::dvec3 size = box.size();
    return size.x * size.y * size.z;
}

double overlapVolume(const Bounds& a, const Bounds& b) {
    const glm::dvec3 size = glm::max(glm::min(a.upper, b.upper) - glm::max(a.lower, b.lower), glm::dvec3(0.0));
    return size.x * size.y * size.z;
}

const Bounds kWorld{{-1.0, 0.0, 2.0}, {3.0, 1.0, 4.0}};

TEST(BlockDecomposition, OneProcessKeepsTheWholeWorld) {
    const BlockDecomposition blocks(kWorld, 1);
    EXPECT_TRUE(blocks.factors().empty());
    EXPECT_EQ(blocks.block(0).lower, kWorld.lower);
    EXPECT_EQ(blocks.block(0).upper, kWorld.upper);
}

// Statistics taken over the blocks count each node once: every point has one owner, a block that
// holds it, the same on every process (on a shared face, the block above it; below).
TEST(BlockDecomposition, EveryPointHasOneOwnerWhoseBlockHoldsIt) {
    for (int count : {1, 2, 3, 4, 6, 8}) {
        SCOPED_TRACE("processes: " + std::to_string(count));
        const BlockDecomposition blocks(kWorld, count);
        // The blocks' own corners and face centres (on shared faces), and a lattice through them.
        std::vector<glm::dvec3> points;
        for (int rank = 0; rank < count; ++rank) {
            const Bounds& block = blocks.block(rank);
            points.push_back(block.lower);
            points.push_back(block.upper);
            points.push_back(0.5 * (block.lower + block.upper));
            for (int axis = 0; axis < 3; ++axis) {
                glm::dvec3 onFace = 0.5 * (block.lower + block.upper);
                onFace[axis] = block.lower[axis];
                points.push_back(onFace);
                onFace[axis] = block.upper[axis];
                points.push_back(onFace);
            }
        }
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j)
                for (int k = 0; k <= 8; ++k)
                    points.push_back(kWorld.lower + glm::dvec3(i, j, k) / 8.0 * kWorld.size());
        for (const glm::dvec3& point : points) {
            const int owner = blocks.ownerOf(point);
            ASSERT_GE(owner, 0);
            ASSERT_LT(owner, count);
            const Bounds& block = blocks.block(owner);
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(point, block.lower)) &&
                        glm::all(glm::lessThanEqual(point, block.upper)))
                << "point " << point.x << " " << point.y << " " << point.z << " is not in its owner's block " << owner;
        }
    }
}

TEST(BlockDecomposition, APointOutsideTheWorldBelongsToTheBlockAtItsNearestFace) {
    const BlockDecomposition blocks(kWorld, 2);  // cut along x at 1.0
    EXPECT_EQ(blocks.ownerOf({-5.0, 0.5, 3.0}), 0);
    EXPECT_EQ(blocks.ownerOf({9.0, 0.5, 3.0}), 1);
    EXPECT_EQ(blocks.ownerOf({3.0 + 1e-12, 1.0 + 1e-12, 4.0 + 1e-12}), 1);
    EXPECT_EQ(blocks.ownerOf({1.0, 0.5, 3.0}), 1);  // on the shared face: the block above it
    EXPECT_EQ(blocks.ownerOf({1.0 - 1e-12, 0.5, 3.0}), 0);
}

TEST(BlockDecomposition, BlocksTileTheWorldForEveryProcessCount) {
    for (int count = 1; count <= 12; ++count) {
        SCOPED_TRACE("processes: " + std::to_string(count));
        const BlockDecomposition blocks(kWorld, count);
        int product = 1;
        for (int factor : blocks.factors()) product *= factor;
        EXPECT_EQ(product, count);
        double total = 0.0;
        for (int rank = 0; rank < count; ++rank) {
            const Bounds& block = blocks.block(rank);
            EXPECT_GT(volume(block), 0.0);
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(block.lower, kWorld.lower)));
            EXPECT_TRUE(glm::all(glm::lessThanEqual(block.upper, kWorld.upper)));
            total += volume(block);
            for (int other = rank + 1; other < count; ++other)
                EXPECT_NEAR(overlapVolume(block, blocks.block(other)), 0.0, 1e-12);
        }
        // Inside the world and without overlaps, the volumes adding up means no gap either.
        EXPECT_NEAR(total, volume(kWorld), 1e-9);
    }
}

TEST(BlockDecomposition, FourProcessesCutTheLongestAxesInHalves) {
    // The world is 4 x 1 x 2: first cut along x, then each half (2 x 1 x 2) along x again (ties go
    // to the lower axis).
    const BlockDecomposition blocks(kWorld, 4);
    EXPECT_EQ(blocks.factors(), (std::vector<int>{2, 2}));
    EXPECT_DOUBLE_EQ(blocks.block(0).lower.x, -1.0);
    EXPECT_DOUBLE_EQ(blocks.block(0).upper.x, 0.0);
    EXPECT_DOUBLE_EQ(blocks.block(1).lower.x, 0.0);
    EXPECT_DOUBLE_EQ(blocks.block(2).lower.x, 1.0);
    EXPECT_DOUBLE_EQ(blocks.block(3).upper.x, 3.0);
    EXPECT_EQ(blocks.splitAxis(0, 1), 0);
    EXPECT_EQ(blocks.splitAxis(0, 0), 0);
}

TEST(BlockDecomposition, GroupsOfARoundAreSlabsOfOneParentInDigitOrder) {
    const BlockDecomposition blocks(kWorld, 12);
    for (int rank = 0; rank < 12; ++rank)
        for (int level = 0; level < int(blocks.factors().size()); ++level) {
            const int axis = blocks.splitAxis(rank, level);
            for (int value = 0; value < blocks.factors()[std::size_t(level)]; ++value) {
                const int partner = blocks.rankWithDigit(rank, level, value);
                EXPECT_EQ(blocks.digit(partner, level), value);
                for (int other = 0; other < int(blocks.factors().size()); ++other) {
                    if (other != level) {
                        EXPECT_EQ(blocks.digit(partner, other), blocks.digit(rank, other));
                    }
                }
                EXPECT_EQ(blocks.splitAxis(partner, level), axis);
                // A higher digit is a slab further along the cut axis.
                if (value > blocks.digit(rank, level)) {
                    EXPECT_GE(blocks.block(partner).lower[axis], blocks.block(rank).upper[axis] - 1e-12);
                }
            }
        }
}

}  // namespace
}  // namespace tstyles
