// Structured-grid geometry: bounds, the spacing rays are sized by, and the validity of its cells.
#include "tstyles/data/structured_grid.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tstyles {
namespace {

std::string cellText(int i, int j, int k) {
    return "(" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) + ")";
}

// The Jacobian determinant of the trilinear map at one corner of a cell: the triple product of
// the three edges leaving that corner, each pointing towards increasing i, j, k.
double cornerDeterminant(const StructuredGrid& grid, int i, int j, int k, int a, int b, int c) {
    const glm::dvec3 corner = grid.node(i + a, j + b, k + c);
    const glm::dvec3 alongI = (grid.node(i + 1 - a, j + b, k + c) - corner) * (a ? -1.0 : 1.0);
    const glm::dvec3 alongJ = (grid.node(i + a, j + 1 - b, k + c) - corner) * (b ? -1.0 : 1.0);
    const glm::dvec3 alongK = (grid.node(i + a, j + b, k + 1 - c) - corner) * (c ? -1.0 : 1.0);
    return glm::dot(alongI, glm::cross(alongJ, alongK));
}

// Edge lengths of a sample of the grid's edges (every edge for small grids), for the percentile.
std::vector<double> sampledEdgeLengths(const StructuredGrid& grid) {
    std::vector<double> lengths;
    const std::size_t total = grid.voxelCount() * 3;
    const std::size_t stride = std::max<std::size_t>(1, total / 300000);
    std::size_t counter = 0;
    for (int k = 0; k < grid.dims.z; ++k)
        for (int j = 0; j < grid.dims.y; ++j)
            for (int i = 0; i < grid.dims.x; ++i) {
                const glm::dvec3 here = grid.node(i, j, k);
                const glm::ivec3 next[3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
                for (int axis = 0; axis < 3; ++axis) {
                    if (next[axis][axis] >= grid.dims[axis] || counter++ % stride != 0) continue;
                    const double length = glm::length(grid.node(next[axis].x, next[axis].y, next[axis].z) - here);
                    if (length > 0.0 && std::isfinite(length)) lengths.push_back(length);
                }
            }
    return lengths;
}

}  // namespace

StructuredGrid makeStructuredGrid(glm::ivec3 dims, std::vector<glm::vec3> nodes,
                                  std::filesystem::path coordinatesFile) {
    return makeStructuredGrid(dims, std::make_shared<const std::vector<glm::vec3>>(std::move(nodes)),
                              std::move(coordinatesFile));
}

StructuredGrid makeStructuredGrid(glm::ivec3 dims, std::shared_ptr<const std::vector<glm::vec3>> nodes,
                                  std::filesystem::path coordinatesFile) {
    StructuredGrid grid;
    grid.dims = dims;
    if (glm::any(glm::lessThan(dims, glm::ivec3(2))))
        throw std::invalid_argument("makeStructuredGrid: dims must be at least 2 along each axis");
    if (!nodes || nodes->size() != grid.voxelCount())
        throw std::invalid_argument("makeStructuredGrid: node count does not match dims");
    grid.nodes = std::move(nodes);
    grid.coordinatesFile = std::move(coordinatesFile);
    grid.localLower = glm::dvec3(std::numeric_limits<double>::infinity());
    grid.localUpper = -grid.localLower;
    for (const glm::vec3& node : *grid.nodes) {
        grid.localLower = glm::min(grid.localLower, glm::dvec3(node));
        grid.localUpper = glm::max(grid.localUpper, glm::dvec3(node));
    }
    std::vector<double> lengths = sampledEdgeLengths(grid);
    if (!lengths.empty()) {
        const auto percentile = lengths.begin() + std::ptrdiff_t(lengths.size() / 20);
        std::nth_element(lengths.begin(), percentile, lengths.end());
        grid.finestEdge = *percentile;
    }
    return grid;
}

std::optional<std::string> findGridProblem(const StructuredGrid& grid) {
    for (int k = 0; k < grid.dims.z; ++k)
        for (int j = 0; j < grid.dims.y; ++j)
            for (int i = 0; i < grid.dims.x; ++i) {
                const glm::vec3 node = (*grid.nodes)[grid.nodeIndex(i, j, k)];
                if (!std::isfinite(node.x) || !std::isfinite(node.y) || !std::isfinite(node.z))
                    return "node " + cellText(i, j, k) + " has a non-finite coordinate";
            }
    // A corner is degenerate when its determinant is tiny against the cube of the cell's size.
    double orientation = 0.0;
    for (int k = 0; k + 1 < grid.dims.z; ++k)
        for (int j = 0; j + 1 < grid.dims.y; ++j)
            for (int i = 0; i + 1 < grid.dims.x; ++i) {
                const double diagonal = glm::length(grid.node(i + 1, j + 1, k + 1) - grid.node(i, j, k));
                const double scale = diagonal * diagonal * diagonal;
                for (int corner = 0; corner < 8; ++corner) {
                    const double determinant =
                        cornerDeterminant(grid, i, j, k, corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
                    if (!(std::abs(determinant) > 1e-9 * scale)) {
                        return "cell " + cellText(i, j, k) + " is degenerate: it has no volume at its corner node " +
                               cellText(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1));
                    }
                    if (orientation == 0.0) orientation = determinant > 0.0 ? 1.0 : -1.0;
                    if (determinant * orientation < 0.0) {
                        std::ostringstream text;
                        text << "cell " << cellText(i, j, k) << " is inverted at its corner node "
                             << cellText(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1))
                             << ": Jacobian determinant " << determinant << " against the "
                             << (orientation > 0.0 ? "right" : "left") << "-handed cell (0, 0, 0)";
                        return text.str();
                    }
                }
            }
    return std::nullopt;
}

}  // namespace tstyles
