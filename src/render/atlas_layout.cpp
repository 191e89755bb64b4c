// Choosing the cell grid of the volume atlas.
#include "tstyles/render/atlas_layout.h"

#include <algorithm>
#include <limits>
#include <string>

#include "tstyles/core/errors.h"

namespace tstyles {

AtlasLayout planAtlas(const std::vector<glm::ivec3>& brickDims, int maxTextureSize) {
    AtlasLayout layout;
    if (brickDims.empty()) return layout;
    for (const auto& dims : brickDims) layout.cellSize = glm::max(layout.cellSize, dims);
    const auto count = static_cast<long long>(brickDims.size());
    const glm::ivec3 maxCells = glm::ivec3(maxTextureSize) / layout.cellSize;
    if (maxCells.x < 1 || maxCells.y < 1 || maxCells.z < 1)
        throwInputError("", "volume atlas",
                        "a time-step of " + std::to_string(layout.cellSize.x) + "x" +
                            std::to_string(layout.cellSize.y) + "x" + std::to_string(layout.cellSize.z) +
                            " samples exceeds the largest 3D texture (" + std::to_string(maxTextureSize) +
                            " per side)");

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
    if (layout.cells.x == 0)
        throwInputError("", "volume atlas",
                        std::to_string(count) + " time-steps do not fit into one 3D texture of at most " +
                            std::to_string(maxTextureSize) + " texels per side");
    layout.size = layout.cells * layout.cellSize;
    for (int index = 0; index < int(count); ++index) {
        const glm::ivec3 cell(index % layout.cells.x, (index / layout.cells.x) % layout.cells.y,
                              index / (layout.cells.x * layout.cells.y));
        layout.brickOrigins.push_back(cell * layout.cellSize);
    }
    return layout;
}

}  // namespace tstyles
