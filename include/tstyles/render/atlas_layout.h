// Packing of many time-step volumes into one 3D texture, so that the number of time-steps is
// bounded by memory, not by texture units: each time-step gets a brick in a grid of equal cells,
// or, where the bricks differ in size (a distributed block of a partial-overlap series keeps some
// time-steps whole and cuts others), in columns that stack them along one axis.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles {

struct AtlasLayout {
    // Equal cells: every brick fits in one cell (the largest dims along each axis). Stacked
    // columns: a column's footprint (the largest dims across the stacking axis) and the tallest
    // column's length along it.
    glm::ivec3 cellSize{0};
    glm::ivec3 cells{0};     // cells (columns) along x, y, z
    glm::ivec3 size{0};      // texture size in texels: cells * cellSize
    std::vector<glm::ivec3> brickOrigins;  // first texel of each brick

    std::size_t texelCount() const { return std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z); }
};

// The arrangement with the fewest texels (then the most cube-like) whose sides stay within
// `maxTextureSize`: equal cells, or for bricks of different sizes (up to 4096 of them) stacked
// columns where those take fewer texels. Throws InputError when the bricks cannot fit into one 3D
// texture.
AtlasLayout planAtlas(const std::vector<glm::ivec3>& brickDims, int maxTextureSize);
// The same, with no layout instead of the InputError.
std::optional<AtlasLayout> tryPlanAtlas(const std::vector<glm::ivec3>& brickDims, int maxTextureSize);

}  // namespace tstyles
