// Empty-space skipping, the data side: each time-step's grid is cut into bricks of kBrickSize³
// cells; a brick keeps the min and max density of the samples it interpolates from, and is
// "visible" when the STF gives some opacity to a density in that range. GL-free.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/render/shader_contract.h"

namespace tstyles {

// 4 rather than 8: the finer grid skips about a quarter of the samples of the super-ellipsoid
// scenes that 8³ bricks left (transparent samples inside partly visible bricks). 2 takes fewer
// samples still now that a ray jumps over cubes of empty bricks (empty_brick_reach.h), but was no
// faster in paired runs and needs eight times the min/max grids (docs/performance.md).
// BRICK_CELLS in shaders/contract.glsl.
inline constexpr int kBrickSize = contract::BRICK_CELLS;

struct BrickGrid {
    glm::ivec3 bricks{0};  // ceil((dims - 1) / kBrickSize) along each axis
    // Per brick (x fastest): min and max density over the samples [b*k, b*k + k] of each axis
    // (clipped to the grid), i.e. every sample a trilinear lookup inside the brick can read.
    std::vector<std::pair<float, float>> minMax;
};

BrickGrid computeBrickGrid(const TimeStep& step);

// The largest opacity of a transfer-function table (entry i at i / (size - 1), linearly
// interpolated between entries) over any density in [low, high], answered in constant time.
class OpacityRangeMaximum {
public:
    explicit OpacityRangeMaximum(const std::vector<glm::vec4>& table);
    float over(float low, float high) const;

private:
    std::vector<std::vector<float>> levels_;  // levels_[k][i]: max of entries i .. i + 2^k - 1
};

// 1 for each brick the STF can make visible, 0 for bricks it leaves fully transparent.
std::vector<std::uint8_t> brickVisibility(const BrickGrid& grid, const OpacityRangeMaximum& opacity);

// Time-steps that share one grid (a packed series): per brick, the largest range over time of the
// densities at one of the samples a lookup inside the brick reads (each sample's largest density
// over the time-steps with data there less its smallest); -1 where no time-step has data in it. A
// trilinear lookup mixes those samples with the same weights in every time-step, and the range of
// a mix is at most the mix of the ranges: so where every time-step has data or none does, no place
// in the brick changes over time by more than its bound, and the largest-change ray mode skips the
// bricks whose bound cannot beat the change it has kept. Throws std::invalid_argument where the
// grids differ.
std::vector<float> brickChangeBounds(std::span<const TimeStep> steps);

}  // namespace tstyles
