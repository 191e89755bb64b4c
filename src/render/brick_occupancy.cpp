// Brick min/max grids and their visibility under a transfer function.
#include "tstyles/render/brick_occupancy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tstyles {

namespace {

glm::ivec3 brickCountOf(glm::ivec3 dims) {
    return glm::max((dims - 1 + kBrickSize - 1) / kBrickSize, glm::ivec3(1));
}

// Calls visit(brick, sample) with the index of every sample of a grid of `dims` (x fastest) and of
// every brick whose range [b*k, b*k + k] contains it (one or two per axis), so that a brick sees
// every sample a trilinear lookup inside it can read.
template <class Visit>
void forEachBrickReading(glm::ivec3 dims, glm::ivec3 bricks, Visit visit) {
    auto bricksOf = [](int sample, int brickCount) {
        const int natural = sample / kBrickSize;
        const int lower = (sample % kBrickSize == 0 && natural > 0) ? natural - 1 : natural;
        return std::pair<int, int>(std::min(lower, brickCount - 1), std::min(natural, brickCount - 1));
    };
    std::size_t index = 0;
    for (int z = 0; z < dims.z; ++z) {
        const auto [z0, z1] = bricksOf(z, bricks.z);
        for (int y = 0; y < dims.y; ++y) {
            const auto [y0, y1] = bricksOf(y, bricks.y);
            for (int x = 0; x < dims.x; ++x, ++index) {
                const auto [x0, x1] = bricksOf(x, bricks.x);
                for (int bz = z0; bz <= z1; ++bz)
                    for (int by = y0; by <= y1; ++by)
                        for (int bx = x0; bx <= x1; ++bx)
                            visit((std::size_t(bz) * std::size_t(bricks.y) + std::size_t(by)) * std::size_t(bricks.x) +
                                      std::size_t(bx),
                                  index);
            }
        }
    }
}

}  // namespace

BrickGrid computeBrickGrid(const TimeStep& step) {
    // Bricks are in computational (voxel) space, so every grid kind is bricked the same way.
    BrickGrid result;
    result.bricks = brickCountOf(step.dims());
    result.minMax.assign(std::size_t(result.bricks.x) * result.bricks.y * result.bricks.z, {1.0f, 0.0f});
    forEachBrickReading(step.dims(), result.bricks, [&](std::size_t brick, std::size_t sample) {
        const float density = step.density[sample];
        // Missing voxels are transparent; a lookup beside them mixes only the valid ones.
        if (isMissing(density)) return;
        auto& range = result.minMax[brick];
        range.first = std::min(range.first, density);
        range.second = std::max(range.second, density);
    });
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

std::vector<float> brickChangeBounds(std::span<const TimeStep> steps) {
    if (steps.empty()) return {};
    const glm::ivec3 dims = steps.front().dims();
    const std::size_t samples = steps.front().density.size();
    // Each sample's range over the time-steps that have data there (lowest > highest: none has).
    std::vector<float> lowest(samples, 1.0f), highest(samples, 0.0f);
    for (const TimeStep& step : steps) {
        if (step.dims() != dims) throw std::invalid_argument("brickChangeBounds: the time-steps' grids differ");
        for (std::size_t sample = 0; sample < samples; ++sample) {
            const float density = step.density[sample];
            if (isMissing(density)) continue;
            lowest[sample] = std::min(lowest[sample], density);
            highest[sample] = std::max(highest[sample], density);
        }
    }
    const glm::ivec3 bricks = brickCountOf(dims);
    std::vector<float> bounds(std::size_t(bricks.x) * bricks.y * bricks.z, -1.0f);
    forEachBrickReading(dims, bricks, [&](std::size_t brick, std::size_t sample) {
        if (lowest[sample] <= highest[sample]) bounds[brick] = std::max(bounds[brick], highest[sample] - lowest[sample]);
    });
    return bounds;
}

}  // namespace tstyles
