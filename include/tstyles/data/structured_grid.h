// An explicit structured (curvilinear) grid: the grid-local position of every node is given, as in
// VTK structured grids or Plot3D. Node (i, j, k) sits at nodes[i + nx * (j + ny * k)]; cell
// (i, j, k) is the trilinear hexahedron spanned by nodes (i..i+1, j..j+1, k..k+1).
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles {

struct StructuredGrid {
    glm::ivec3 dims{0};
    // Shared by every time-step that uses the same grid (one coordinates file, one inverse map).
    std::shared_ptr<const std::vector<glm::vec3>> nodes;
    // Where the coordinates came from (for messages and `tstyles info`); empty when made in memory.
    std::filesystem::path coordinatesFile;
    // Grid-local axis-aligned bounds of the nodes.
    glm::dvec3 localLower{0.0};
    glm::dvec3 localUpper{0.0};
    // The sample spacing the renderer sizes its rays by: the 5th percentile of the cell edge
    // lengths (the very smallest edge of a grid clustered at a wall would make rays crawl).
    double finestEdge = 1.0;

    std::size_t voxelCount() const {
        return std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
    }
    std::size_t nodeIndex(int i, int j, int k) const {
        return std::size_t(i) + std::size_t(dims.x) * (std::size_t(j) + std::size_t(dims.y) * std::size_t(k));
    }
    glm::dvec3 node(int i, int j, int k) const { return glm::dvec3((*nodes)[nodeIndex(i, j, k)]); }
};

// Makes a grid from its node positions and fills in the bounds and the finest edge. Throws
// std::invalid_argument when the node count does not match dims (a caller's bug; readers check
// sizes first and report them as input errors).
StructuredGrid makeStructuredGrid(glm::ivec3 dims, std::vector<glm::vec3> nodes,
                                  std::filesystem::path coordinatesFile = {});
StructuredGrid makeStructuredGrid(glm::ivec3 dims, std::shared_ptr<const std::vector<glm::vec3>> nodes,
                                  std::filesystem::path coordinatesFile = {});

// What is wrong with a grid that cannot be rendered, or nothing: a non-finite coordinate, a
// degenerate cell (a corner where the cell has no volume) or an inverted cell (turned inside out
// against the orientation of the grid's first cell). The text names the node or cell.
std::optional<std::string> findGridProblem(const StructuredGrid& grid);

}  // namespace tstyles
