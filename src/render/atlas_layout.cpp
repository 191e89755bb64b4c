// Choosing the cell grid of the volume atlas.
#include "tstyles/render/atlas_layout.h"

#include <algorithm>
#include <limits>
#include <string>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

glm::ivec3 largestDims(const std::vector<glm::ivec3>& brickDims) {
    glm::ivec3 largest(0);
    for (const auto& dims : brickDims) largest = glm::max(largest, dims);
    return largest;
}

}  // namespace

std::optional<AtlasLayout> tryPlanAtlas(const std::vector<glm::ivec3>& brickDims, int maxTextureSize) {
    AtlasLayout layout;
    if (brickDims.empty()) return layout;
    layout.cellSize = largestDims(brickDims);
    const auto count = static_cast<long long>(brickDims.size());
    const glm::ivec3 maxCells = glm::ivec3(maxTextureSize) / layout.cellSize;
    if (maxCells.x < 1 || maxCells.y < 1 || maxCells.z < 1) return std::nullopt;

    long long bestTexels = std::numeric_limits<long long>::max();
    long long bestLongestSide = std::numeric_limits<long long>::max();
    for (long long cx = 1; cx <= std::min<long long>(count, maxCells.x); ++cx) {
        const long long rowsNeeded = (count + cx - 1) / cx;
        for (long long cy = 1; cy <= std::min<long long>(rowsNeeded, maxCells.y); ++cy) {
            const long long cz = (count + cx * cy - 1) / (cx * cy);
            if (cz > maxCells.z) continue;
            const glm::i64vec3 size = glm::i64vec3(cx, cy, cz) * glm::i64vec3(layout.cellSize);
            const long long texels = size.x * size.y * size.z;
            const long long longestSide = std::max({size.x, size.y, size.z});
            if (texels < bestTexels || (texels == bestTexels && longestSide < bestLongestSide)) {
                bestTexels = texels;
                bestLongestSide = longestSide;
                layout.cells = glm::ivec3(int(cx), int(cy), int(cz));
            }
        }
    }
    if (layout.cells.x == 0) return std::nullopt;
    layout.size = layout.cells * layout.cellSize;
    for (int index = 0; index < int(count); ++index) {
        const glm::ivec3 cell(index % layout.cells.x, (index / layout.cells.x) % layout.cells.y,
                              index / (layout.cells.x * layout.cells.y));
        layout.brickOrigins.push_back(cell * layout.cellSize);
    }
    return layout;
}

AtlasLayout planAtlas(const std::vector<glm::ivec3>& brickDims, int maxTextureSize) {
    if (std::optional<AtlasLayout> layout = tryPlanAtlas(brickDims, maxTextureSize)) return *layout;
    const glm::ivec3 cellSize = largestDims(brickDims);
    if (glm::any(glm::greaterThan(cellSize, glm::ivec3(maxTextureSize))))
        throwInputError("", "volume atlas",
                        "a time-step of " + std::to_string(cellSize.x) + "x" + std::to_string(cellSize.y) + "x" +
                            std::to_string(cellSize.z) + " samples exceeds the largest 3D texture (" +
                            std::to_string(maxTextureSize) + " per side)");
    throwInputError("", "volume atlas",
                    std::to_string(brickDims.size()) + " time-steps do not fit into one 3D texture of at most " +
                        std::to_string(maxTextureSize) + " texels per side");
}

}  // namespace tstyles
