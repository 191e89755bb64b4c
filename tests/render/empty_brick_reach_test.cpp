// The reach of empty bricks (render/empty_brick_reach.h): how far a ray in an empty brick may jump
// over the empty bricks around it. Closed forms on a line and an empty grid, and the definition
// (1 + the Chebyshev distance to the nearest visible brick, less one, capped) on random grids.
#include <algorithm>
#include <cstdlib>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "tstyles/render/empty_brick_reach.h"

namespace tstyles {
namespace {

std::size_t indexOf(const glm::ivec3& brick, const glm::ivec3& bricks) {
    return (std::size_t(brick.z) * std::size_t(bricks.y) + std::size_t(brick.y)) * std::size_t(bricks.x) +
           std::size_t(brick.x);
}

TEST(EmptyBrickReach, OnALineItIsTheDistanceToTheVisibleBrick) {
    const glm::ivec3 bricks(21, 1, 1);
    std::vector<std::uint8_t> visible(21, 0);
    visible[4] = 255;
    const std::vector<std::uint8_t> reach = emptyBrickReach(visible, bricks);
    for (int x = 0; x < 21; ++x)
        EXPECT_EQ(int(reach[std::size_t(x)]), std::min(std::abs(x - 4), kMaxEmptyReach + 1)) << "brick " << x;
}

TEST(EmptyBrickReach, AnEmptyGridReachesTheCapEverywhere) {
    const glm::ivec3 bricks(20, 17, 3);
    const std::vector<std::uint8_t> reach =
        emptyBrickReach(std::vector<std::uint8_t>(std::size_t(20 * 17 * 3), 0), bricks);
    EXPECT_TRUE(std::all_of(reach.begin(), reach.end(), [](std::uint8_t r) { return r == kMaxEmptyReach + 1; }));
}

TEST(EmptyBrickReach, EveryBrickOfTheCubeItNamesIsEmptyAndTheNextCubeIsNot) {
    std::mt19937 random(17);
    for (const glm::ivec3 bricks : {glm::ivec3(23, 19, 11), glm::ivec3(40, 6, 9)}) {
        for (const double visibleShare : {0.002, 0.02, 0.2}) {
            std::bernoulli_distribution isVisible(visibleShare);
            std::vector<std::uint8_t> visible(std::size_t(bricks.x) * bricks.y * bricks.z);
            for (auto& brick : visible) brick = isVisible(random) ? 255 : 0;
            const std::vector<std::uint8_t> reach = emptyBrickReach(visible, bricks);
            for (int z = 0; z < bricks.z; ++z)
                for (int y = 0; y < bricks.y; ++y)
                    for (int x = 0; x < bricks.x; ++x) {
                        const glm::ivec3 brick(x, y, z);
                        // The Chebyshev distance to the nearest visible brick (none: beyond the cap).
                        int nearest = kMaxEmptyReach + 2;
                        for (int vz = 0; vz < bricks.z; ++vz)
                            for (int vy = 0; vy < bricks.y; ++vy)
                                for (int vx = 0; vx < bricks.x; ++vx)
                                    if (visible[indexOf({vx, vy, vz}, bricks)] != 0)
                                        nearest = std::min(nearest, std::max({std::abs(vx - x), std::abs(vy - y),
                                                                              std::abs(vz - z)}));
                        const int expected = nearest == 0 ? 0 : std::min(nearest, kMaxEmptyReach + 1);
                        ASSERT_EQ(int(reach[indexOf(brick, bricks)]), expected)
                            << "brick (" << x << ", " << y << ", " << z << ") of " << bricks.x << "x" << bricks.y
                            << "x" << bricks.z << ", visible share " << visibleShare;
                    }
        }
    }
}

TEST(EmptyBrickReach, AVisibilityOfAnotherSizeIsRefused) {
    EXPECT_THROW(emptyBrickReach(std::vector<std::uint8_t>(5, 0), glm::ivec3(2, 2, 2)), std::invalid_argument);
}

}  // namespace
}  // namespace tstyles
