// Choosing the cell grid of the volume atlas.
#include "tstyles/render/atlas_layout.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <string>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

glm::ivec3 largestDims(const std::vector<glm::ivec3>& brickDims) {
    glm::ivec3 largest(0);
    for (const auto& dims : brickDims) largest = glm::max(largest, dims);
    return largest;
}

// Stacking is tried for at most this many bricks of different sizes; beyond, equal cells.
constexpr std::size_t kMostStackedBricks = 4096;

long long texelsOf(const glm::i64vec3& size) { return size.x * size.y * size.z; }

// Bricks stacked along z in `columnCount` columns of the largest x and y, filled tallest first
// into the lowest column; the columns side by side in x, then in rows along y. None where no
// arrangement of them fits.
std::optional<AtlasLayout> stackedColumns(const std::vector<glm::ivec3>& brickDims, std::size_t columnCount,
                                          const std::vector<std::size_t>& tallestFirst, int maxTextureSize) {
    const glm::ivec3 largest = largestDims(brickDims);
    // The lowest column on top (then the first): (height, column) in a min-heap.
    std::priority_queue<std::pair<int, std::size_t>, std::vector<std::pair<int, std::size_t>>, std::greater<>> lowest;
    for (std::size_t column = 0; column < columnCount; ++column) lowest.emplace(0, column);
    std::vector<std::size_t> columnOf(brickDims.size());
    std::vector<int> zOf(brickDims.size());
    int height = 0;
    for (std::size_t brick : tallestFirst) {
        const auto [columnHeight, column] = lowest.top();
        lowest.pop();
        columnOf[brick] = column;
        zOf[brick] = columnHeight;
        height = std::max(height, columnHeight + brickDims[brick].z);
        lowest.emplace(columnHeight + brickDims[brick].z, column);
    }
    if (height > maxTextureSize) return std::nullopt;
    const long long maxX = maxTextureSize / largest.x;
    const long long maxY = maxTextureSize / largest.y;
    const auto columns = static_cast<long long>(columnCount);
    std::optional<glm::i64vec3> best;
    for (long long cx = 1; cx <= std::min(columns, maxX); ++cx) {
        const long long cy = (columns + cx - 1) / cx;
        if (cy > maxY) continue;
        const glm::i64vec3 size(cx * largest.x, cy * largest.y, height);
        if (!best || texelsOf(size) < texelsOf(*best)) best = size;
    }
    if (!best) return std::nullopt;
    AtlasLayout layout;
    layout.cellSize = glm::ivec3(largest.x, largest.y, height);
    layout.cells = glm::ivec3(int(best->x / largest.x), int(best->y / largest.y), 1);
    layout.size = glm::ivec3(*best);
    for (std::size_t brick = 0; brick < brickDims.size(); ++brick) {
        const int column = int(columnOf[brick]);
        layout.brickOrigins.push_back(
            glm::ivec3(column % layout.cells.x * largest.x, column / layout.cells.x * largest.y, zOf[brick]));
    }
    return layout;
}

// The column counts tried: every count up to 16, then about 25 % apart, and one per brick; so a
// plan costs count log^2 count, not count^2 log count (fitToGpuMemory plans many scales).
std::vector<std::size_t> columnCounts(std::size_t bricks) {
    std::vector<std::size_t> counts;
    for (std::size_t columns = 1; columns <= bricks; columns = columns < 16 ? columns + 1 : columns + columns / 4)
        counts.push_back(columns);
    if (counts.back() != bricks) counts.push_back(bricks);
    return counts;
}

// `v` with its axes rotated so that `axis` comes last (z): stacking along z then stacks along `axis`.
glm::ivec3 axisLast(glm::ivec3 v, int axis) { return glm::ivec3(v[(axis + 1) % 3], v[(axis + 2) % 3], v[axis]); }
glm::ivec3 axisBack(glm::ivec3 v, int axis) {
    glm::ivec3 back(0);
    back[(axis + 1) % 3] = v.x;
    back[(axis + 2) % 3] = v.y;
    back[axis] = v.z;
    return back;
}

// The stacked arrangement with the fewest texels over the three stacking axes and every column
// count; none where none fits. (A block cut along x differs in x: its bricks stack along x.)
std::optional<AtlasLayout> bestStackedColumns(const std::vector<glm::ivec3>& brickDims, int maxTextureSize) {
    std::optional<AtlasLayout> best;
    for (int axis = 0; axis < 3; ++axis) {
        std::vector<glm::ivec3> turned;
        for (const glm::ivec3& dims : brickDims) turned.push_back(axisLast(dims, axis));
        std::vector<std::size_t> tallestFirst(turned.size());
        for (std::size_t brick = 0; brick < turned.size(); ++brick) tallestFirst[brick] = brick;
        std::stable_sort(tallestFirst.begin(), tallestFirst.end(),
                         [&](std::size_t a, std::size_t b) { return turned[a].z > turned[b].z; });
        for (std::size_t columns : columnCounts(turned.size())) {
            std::optional<AtlasLayout> layout = stackedColumns(turned, columns, tallestFirst, maxTextureSize);
            if (!layout || (best && layout->texelCount() >= best->texelCount())) continue;
            layout->cellSize = axisBack(layout->cellSize, axis);
            layout->cells = axisBack(layout->cells, axis);
            layout->size = axisBack(layout->size, axis);
            for (glm::ivec3& origin : layout->brickOrigins) origin = axisBack(origin, axis);
            best = std::move(layout);
        }
    }
    return best;
}

// Equal cells of the largest brick's size in a 3D grid; none where they do not fit.
std::optional<AtlasLayout> equalCells(const std::vector<glm::ivec3>& brickDims, int maxTextureSize) {
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

}  // namespace

std::optional<AtlasLayout> tryPlanAtlas(const std::vector<glm::ivec3>& brickDims, int maxTextureSize) {
    std::optional<AtlasLayout> equal = equalCells(brickDims, maxTextureSize);
    if (brickDims.size() < 2 || brickDims.size() > kMostStackedBricks) return equal;
    const glm::ivec3 largest = largestDims(brickDims);
    const bool allAlike = std::all_of(brickDims.begin(), brickDims.end(), [&](glm::ivec3 dims) { return dims == largest; });
    if (allAlike) return equal;  // equal cells waste nothing then
    std::optional<AtlasLayout> stacked = bestStackedColumns(brickDims, maxTextureSize);
    if (stacked && (!equal || stacked->texelCount() < equal->texelCount())) return stacked;
    return equal;
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
