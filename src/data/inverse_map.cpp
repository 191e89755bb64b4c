// Building an inverse map by point location at every texel, and reading it back like the GPU does.
#include "tstyles/data/inverse_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tstyles/data/structured_point_location.h"

namespace tstyles {
namespace {

constexpr int kMaxMapTexelsPerAxis = 256;

std::size_t texelIndex(glm::ivec3 dims, int x, int y, int z) {
    return (std::size_t(z) * std::size_t(dims.y) + std::size_t(y)) * std::size_t(dims.x) + std::size_t(x);
}

// How far local coordinates lie outside the unit cube (0 inside).
double excess(glm::dvec3 uvw) {
    const glm::dvec3 below = glm::max(-uvw, glm::dvec3(0.0));
    const glm::dvec3 above = glm::max(uvw - 1.0, glm::dvec3(0.0));
    return glm::length(below + above);
}

// An outside texel next to the grid: extrapolate the cells of its inside neighbours and keep the
// one it is least far outside of.
glm::dvec3 extrapolate(const StructuredGrid& grid, const InverseMap& map, const std::vector<char>& inside,
                       glm::ivec3 texel, glm::dvec3 point, bool& found) {
    double best = std::numeric_limits<double>::infinity();
    glm::dvec3 result(0.0);
    found = false;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const glm::ivec3 neighbour = texel + glm::ivec3(dx, dy, dz);
                if (glm::any(glm::lessThan(neighbour, glm::ivec3(0))) ||
                    glm::any(glm::greaterThanEqual(neighbour, map.dims)))
                    continue;
                const std::size_t index = texelIndex(map.dims, neighbour.x, neighbour.y, neighbour.z);
                if (!inside[index]) continue;
                const glm::ivec3 cell = glm::clamp(glm::ivec3(glm::floor(glm::dvec3(map.texels[index]))),
                                                   glm::ivec3(0), grid.dims - 2);
                const auto uvw = solveCellCoordinates(grid, cell, point);
                if (!uvw || excess(*uvw) >= best) continue;
                best = excess(*uvw);
                result = glm::dvec3(cell) + *uvw;
                found = true;
            }
    // Not clamped: filtering between this texel and its inside neighbours then follows the cell's
    // map linearly up to the boundary; lookups clamp after filtering.
    return result;
}

}  // namespace

glm::ivec3 inverseMapDims(const StructuredGrid& grid, int texelsPerCell) {
    return glm::min((grid.dims - 1) * texelsPerCell + 1, glm::ivec3(kMaxMapTexelsPerAxis));
}

InverseMap buildInverseMap(const StructuredGrid& grid, glm::ivec3 dims) {
    if (glm::any(glm::lessThan(dims, glm::ivec3(2))))
        throw std::invalid_argument("buildInverseMap: dims must be at least 2 along each axis");
    InverseMap map;
    map.dims = dims;
    map.gridDims = grid.dims;
    map.lower = grid.localLower;
    map.upper = grid.localUpper;
    map.texels.assign(std::size_t(dims.x) * dims.y * dims.z, glm::vec4(0.0f));
    const glm::dvec3 texelSize = (map.upper - map.lower) / glm::dvec3(dims - 1);
    auto positionOf = [&](int x, int y, int z) { return map.lower + glm::dvec3(x, y, z) * texelSize; };

    const StructuredPointLocator locator(grid);
    std::vector<char> inside(map.texels.size(), 0);
    glm::ivec3 hint(0);
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x) {
                const auto computational = locator.locate(positionOf(x, y, z), &hint);
                if (!computational) continue;
                const std::size_t index = texelIndex(dims, x, y, z);
                map.texels[index] = glm::vec4(glm::vec3(*computational), 1.0f);
                inside[index] = 1;
            }
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x) {
                const std::size_t index = texelIndex(dims, x, y, z);
                if (inside[index]) continue;
                bool found = false;
                const glm::dvec3 coordinates =
                    extrapolate(grid, map, inside, glm::ivec3(x, y, z), positionOf(x, y, z), found);
                if (found) map.texels[index] = glm::vec4(glm::vec3(coordinates), 0.0f);
            }
    return map;
}

glm::vec4 InverseMap::lookup(glm::dvec3 local) const {
    const glm::dvec3 scaled =
        glm::clamp((local - lower) / (upper - lower) * glm::dvec3(dims - 1), glm::dvec3(0.0), glm::dvec3(dims - 1));
    const glm::ivec3 base = glm::min(glm::ivec3(glm::floor(scaled)), dims - 2);
    const glm::dvec3 t = scaled - glm::dvec3(base);
    glm::dvec4 result(0.0);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 bit(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const double weight = (bit.x ? t.x : 1.0 - t.x) * (bit.y ? t.y : 1.0 - t.y) * (bit.z ? t.z : 1.0 - t.z);
        const glm::ivec3 texel = base + bit;
        result += weight * glm::dvec4(texels[texelIndex(dims, texel.x, texel.y, texel.z)]);
    }
    const glm::dvec3 clamped = glm::clamp(glm::dvec3(result), glm::dvec3(0.0), glm::dvec3(gridDims - 1));
    return glm::vec4(glm::vec3(clamped), float(result.a));
}

}  // namespace tstyles
