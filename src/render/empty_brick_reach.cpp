// The reach of empty bricks, by eroding the set of empty bricks one brick at a time.
#include "tstyles/render/empty_brick_reach.h"

#include <cstddef>
#include <stdexcept>

namespace tstyles {
namespace {

// Keeps a brick in `empty` only where its two neighbours along `axis` are empty too (or outside the
// grid): one brick of erosion along one axis. Three of them, one per axis, erode by the 3x3x3 cube.
// Row by row along x, so that the inner loops are plain and the compiler can vectorise them.
void erodeAlong(int axis, const glm::ivec3& bricks, std::vector<std::uint8_t>& empty,
                std::vector<std::uint8_t>& scratch) {
    const std::size_t width = std::size_t(bricks.x);
    const std::size_t plane = width * std::size_t(bricks.y);
    for (int z = 0; z < bricks.z; ++z)
        for (int y = 0; y < bricks.y; ++y) {
            const std::size_t row = std::size_t(z) * plane + std::size_t(y) * width;
            const std::uint8_t* here = empty.data() + row;
            std::uint8_t* out = scratch.data() + row;
            if (axis == 0) {
                for (std::size_t x = 0; x < width; ++x) {
                    const std::uint8_t before = x > 0 ? here[x - 1] : 1;
                    const std::uint8_t after = x + 1 < width ? here[x + 1] : 1;
                    out[x] = here[x] & before & after;
                }
                continue;
            }
            const bool first = axis == 1 ? y == 0 : z == 0;
            const bool last = axis == 1 ? y == bricks.y - 1 : z == bricks.z - 1;
            const std::size_t stride = axis == 1 ? width : plane;
            const std::uint8_t* before = first ? here : here - stride;  // outside the grid: itself
            const std::uint8_t* after = last ? here : here + stride;
            for (std::size_t x = 0; x < width; ++x) out[x] = here[x] & before[x] & after[x];
        }
    empty.swap(scratch);
}

}  // namespace

std::vector<std::uint8_t> emptyBrickReach(const std::vector<std::uint8_t>& visible, const glm::ivec3& bricks) {
    const std::size_t count = std::size_t(bricks.x) * std::size_t(bricks.y) * std::size_t(bricks.z);
    if (visible.size() != count)
        throw std::invalid_argument("emptyBrickReach: visibility does not match the brick grid");
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
        for (std::size_t brick = 0; brick < count; ++brick) {
            reach[brick] = empty[brick] ? std::uint8_t(radius + 1) : reach[brick];
            remaining += empty[brick];
        }
    }
    return reach;
}

}  // namespace tstyles
