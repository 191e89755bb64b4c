// Empty-space skipping over more than one brick: for each empty brick, how far the empty bricks
// around it reach (a Chebyshev distance to the nearest visible brick, capped), so that a ray in it
// may jump to where it leaves the whole empty cube instead of stopping at every brick's face.
// This is what the occupancy textures hold (shaders/volume_sampling.glsl, emptyReachAt). GL-free.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles {

// The largest reach recorded: an empty cube at most 2 * 7 + 1 = 15 bricks wide. Larger cubes save
// little more (a ray crosses a cube in one jump either way), and each step of reach costs a pass
// over the bricks at every change of the transfer function.
inline constexpr int kMaxEmptyReach = 7;

// Per brick of a `bricks`-sized grid (x fastest), given its visibility (non-zero: visible): 0 for a
// visible brick; for an empty one 1 + r, where r <= kMaxEmptyReach is the largest radius such that
// every brick at most r bricks away along each axis is empty (bricks outside the grid are not
// counted, so a cube at the grid's edge is cut by it).
std::vector<std::uint8_t> emptyBrickReach(const std::vector<std::uint8_t>& visible, const glm::ivec3& bricks);

}  // namespace tstyles
