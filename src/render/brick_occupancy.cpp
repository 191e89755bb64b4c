// Brick min/max grids and their visibility under a transfer function.
#include "tstyles/render/brick_occupancy.h"

#include <algorithm>
#include <cmath>

namespace tstyles {

BrickGrid computeBrickGrid(const TimeStep& step) {
    // Bricks are in computational (voxel) space, so every grid kind is bricked the same way.
    const glm::ivec3 dims = step.dims();
    BrickGrid result;
    result.bricks = glm::max((dims - 1 + kBrickSize - 1) / kBrickSize, glm::ivec3(1));
    result.minMax.assign(std::size_t(result.bricks.x) * result.bricks.y * result.bricks.z, {1.0f, 0.0f});
    // Each sample updates every brick whose range [b*k, b*k + k] contains it (one or two per axis).
    auto bricksOf = [](int sample, int brickCount) {
        const int natural = sample / kBrickSize;
        const int lower = (sample % kBrickSize == 0 && natural > 0) ? natural - 1 : natural;
        return std::pair<int, int>(std::min(lower, brickCount - 1), std::min(natural, brickCount - 1));
    };
    std::size_t index = 0;
    for (int z = 0; z < dims.z; ++z) {
        const auto [z0, z1] = bricksOf(z, result.bricks.z);
        for (int y = 0; y < dims.y; ++y) {
            const auto [y0, y1] = bricksOf(y, result.bricks.y);
            for (int x = 0; x < dims.x; ++x, ++index) {
                const auto [x0, x1] = bricksOf(x, result.bricks.x);
                const float density = step.density[index];
                // Missing voxels are transparent; a lookup beside them mixes only the valid ones.
                if (isMissing(density)) continue;
                for (int bz = z0; bz <= z1; ++bz)
                    for (int by = y0; by <= y1; ++by)
                        for (int bx = x0; bx <= x1; ++bx) {
                            auto& range = result.minMax[(std::size_t(bz) * result.bricks.y + by) * result.bricks.x + bx];
                            range.first = std::min(range.first, density);
                            range.second = std::max(range.second, density);
                        }
            }
        }
    }
    return result;
}

OpacityRangeMaximum::OpacityRangeMaximum(const std::vector<glm::vec4>& table) {
    std::vector<float> level(table.size());
    std::transform(table.begin(), table.end(), level.begin(), [](const glm::vec4& entry) { return entry.a; });
    levels_.push_back(std::move(level));
    for (std::size_t width = 2; width <= table.size(); width *= 2) {
        const auto& previous = levels_.back();
        std::vector<float> next(table.size() - width + 1);
        for (std::size_t i = 0; i < next.size(); ++i) next[i] = std::max(previous[i], previous[i + width / 2]);
        levels_.push_back(std::move(next));
    }
}

float OpacityRangeMaximum::over(float low, float high) const {
    const int size = int(levels_[0].size());
    // Entries that take part in interpolating any density in [low, high].
    const int first = std::clamp(int(std::floor(std::clamp(low, 0.0f, 1.0f) * float(size - 1))), 0, size - 1);
    const int last = std::clamp(int(std::ceil(std::clamp(high, 0.0f, 1.0f) * float(size - 1))), first, size - 1);
    const int count = last - first + 1;
    const int level = int(std::floor(std::log2(double(count))));
    const int width = 1 << level;
    return std::max(levels_[std::size_t(level)][std::size_t(first)], levels_[std::size_t(level)][std::size_t(last - width + 1)]);
}

std::vector<std::uint8_t> brickVisibility(const BrickGrid& grid, const OpacityRangeMaximum& opacity) {
    std::vector<std::uint8_t> visible(grid.minMax.size());
    std::transform(grid.minMax.begin(), grid.minMax.end(), visible.begin(), [&](const auto& range) {
        // A brick without any data keeps its empty range (min > max) and shows nothing.
        if (range.first > range.second) return std::uint8_t(0);
        return std::uint8_t(opacity.over(range.first, range.second) > 0.0f ? 255 : 0);
    });
    return visible;
}

}  // namespace tstyles
