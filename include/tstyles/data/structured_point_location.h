// Point location in an explicit structured grid: which cell holds a grid-local point, and where in
// that cell (Newton iteration on the cell's trilinear map). A coarse bucket grid of cell bounding
// boxes narrows the search to a few cells.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/structured_grid.h"

namespace tstyles {

// The trilinear map of cell `cell` at local coordinates `uvw` in [0, 1]^3.
glm::dvec3 cellPosition(const StructuredGrid& grid, glm::ivec3 cell, glm::dvec3 uvw);

// The grid-local position of computational coordinates (i, j, k) (fractional, inside the grid).
glm::dvec3 positionAtComputational(const StructuredGrid& grid, glm::dvec3 computational);

// Newton iteration for the local coordinates of `point` in cell `cell`, not restricted to the
// cell (points just outside extrapolate the cell's map). Nothing when it does not converge.
std::optional<glm::dvec3> solveCellCoordinates(const StructuredGrid& grid, glm::ivec3 cell, glm::dvec3 point);

class StructuredPointLocator {
public:
    explicit StructuredPointLocator(const StructuredGrid& grid);

    // The computational coordinates (i, j, k) of a grid-local point inside the grid, or nothing
    // when it lies outside every cell. `hint` (a cell) is tried first and updated to the cell
    // found, which makes walks over neighbouring points cheap.
    std::optional<glm::dvec3> locate(glm::dvec3 point, glm::ivec3* hint = nullptr) const;

    const StructuredGrid& grid() const { return *grid_; }

private:
    std::optional<glm::dvec3> tryCell(glm::ivec3 cell, glm::dvec3 point) const;

    const StructuredGrid* grid_;
    glm::ivec3 buckets_{1};
    glm::dvec3 bucketScale_{1.0};  // buckets per local unit
    std::vector<std::uint32_t> bucketStart_;  // CSR: cells of bucket b are cells_[start[b] .. start[b+1])
    std::vector<std::uint32_t> cells_;
};

}  // namespace tstyles
