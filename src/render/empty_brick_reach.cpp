// The reach of empty bricks, by eroding the set of empty bricks one brick at a time.
#include "tstyles/render/empty_brick_reach.h"

#include <cstddef>
#include <stdexcept>

namespace tstyles {
namespace {

// Keeps a brick in `empty` only where its two neighbours along `axis` are empty too (or outside the
// grid): one brick of erosion along one axis. Three of them, one per axis, erode by the 3x3x3 cube.
void erodeAlong(int axis, const glm::ivec3& bricks, std::vector<std::uint8_t>& empty,
                std::vector<std::uint8_t>& scratch) {
    const std::size_t stride = axis == 0 ? 1 : axis == 1 ? std::size_t(bricks.x) : std::size_t(bricks.x) * bricks.y;
    const int length = bricks[axis];
    std::size_t index = 0;
    for (int z = 0; z < bricks.z; ++z)
        for (int y = 0; y < bricks.y; ++y)
            for (int x = 0; x < bricks.x; ++x, ++index) {
                const int along = axis == 0 ? x : axis == 1 ? y : z;
                const bool before = along == 0 || empty[index - stride];
                const bool after = along == length - 1 || empty[index + stride];
                scratch[index] = std::uint8_t(empty[index] && before && after);
            }
    empty.swap(scratch);
}

}  // namespace

std::vector<std::uint8_t> emptyBrickReach(const std::vector<std::uint8_t>& visible, const glm::ivec3& bricks) {
    const std::size_t count = std::size_t(bricks.x) * std::size_t(bricks.y) * std::size_t(bricks.z);
    if (visible.size() != count) throw std::invalid_argument("emptyBrickReach: visibility does not match the brick grid");
    std::vector<std::uint8_t> reach(count), empty(count), scratch(count);
    std::size_t remaining = 0;
    for (std::size_t brick = 0; brick < count; ++brick) {
        empty[brick] = visible[brick] == 0;
        reach[brick] = empty[brick];
        remaining += empty[brick];
    }
    // After r rounds, `empty` holds the bricks whose cube of radius r is empty.
    for (int radius = 1; radius <= kMaxEmptyReach && remaining > 0; ++radius) {
        for (int axis = 0; axis < 3; ++axis) erodeAlong(axis, bricks, empty, scratch);
        remaining = 0;
        for (std::size_t brick = 0; brick < count; ++brick)
            if (empty[brick]) {
                reach[brick] = std::uint8_t(radius + 1);
                ++remaining;
            }
    }
    return reach;
}

}  // namespace tstyles
