// Point location in a structured grid: bucket grid of cell bounding boxes, then Newton iteration in
// each candidate cell's trilinear hexahedron.
#include "tstyles/data/structured_point_location.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tstyles {
namespace {

constexpr int kMaxNewtonIterations = 30;
// Local-coordinate slack for "inside the cell": points on a shared face belong to both cells, and
// nodes are float, so a point on the boundary may sit a rounding error outside.
constexpr double kInsideTolerance = 1e-5;
constexpr int kMaxBucketsPerAxis = 96;

struct CellCorners {
    std::array<glm::dvec3, 8> corner;  // corner a + 2b + 4c at (i + a, j + b, k + c)
};

CellCorners cornersOf(const StructuredGrid& grid, glm::ivec3 cell) {
    CellCorners corners;
    for (int index = 0; index < 8; ++index)
        corners.corner[std::size_t(index)] =
            grid.node(cell.x + (index & 1), cell.y + ((index >> 1) & 1), cell.z + ((index >> 2) & 1));
    return corners;
}

glm::dvec3 trilinear(const CellCorners& corners, glm::dvec3 uvw) {
    glm::dvec3 result(0.0);
    for (int index = 0; index < 8; ++index) {
        const double weight = ((index & 1) ? uvw.x : 1.0 - uvw.x) * (((index >> 1) & 1) ? uvw.y : 1.0 - uvw.y) *
                              (((index >> 2) & 1) ? uvw.z : 1.0 - uvw.z);
        result += weight * corners.corner[std::size_t(index)];
    }
    return result;
}

// Columns: d(position)/du, d/dv, d/dw.
glm::dmat3 jacobian(const CellCorners& corners, glm::dvec3 uvw) {
    glm::dmat3 result(0.0);
    for (int index = 0; index < 8; ++index) {
        const glm::dvec3 bit((index & 1), ((index >> 1) & 1), ((index >> 2) & 1));
        const glm::dvec3 factor = glm::mix(1.0 - uvw, uvw, bit);   // the weight's factor per axis
        const glm::dvec3 slope = bit * 2.0 - 1.0;                   // its derivative per axis
        const glm::dvec3& position = corners.corner[std::size_t(index)];
        result[0] += slope.x * factor.y * factor.z * position;
        result[1] += factor.x * slope.y * factor.z * position;
        result[2] += factor.x * factor.y * slope.z * position;
    }
    return result;
}

std::optional<glm::dvec3> newton(const CellCorners& corners, glm::dvec3 point) {
    glm::dvec3 uvw(0.5);
    const double size = glm::length(corners.corner[7] - corners.corner[0]);
    for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
        const glm::dvec3 residual = trilinear(corners, uvw) - point;
        const glm::dmat3 j = jacobian(corners, uvw);
        const double determinant = glm::determinant(j);
        if (!(std::abs(determinant) > 0.0)) return std::nullopt;
        const glm::dvec3 change = glm::inverse(j) * residual;
        uvw -= change;
        // Far outside the cell the map is meaningless; stop early.
        if (glm::any(glm::greaterThan(glm::abs(uvw - 0.5), glm::dvec3(4.0)))) return std::nullopt;
        if (glm::length(change) < 1e-12 && glm::length(residual) <= 1e-9 * size) return uvw;
        if (glm::length(change) < 1e-13) return uvw;
    }
    // Newton converges quadratically on valid cells; the last iterate is good unless it diverged.
    return glm::length(trilinear(corners, uvw) - point) <= 1e-7 * size ? std::optional(uvw) : std::nullopt;
}

}  // namespace

glm::dvec3 cellPosition(const StructuredGrid& grid, glm::ivec3 cell, glm::dvec3 uvw) {
    return trilinear(cornersOf(grid, cell), uvw);
}

glm::dvec3 positionAtComputational(const StructuredGrid& grid, glm::dvec3 computational) {
    const glm::ivec3 cell = glm::clamp(glm::ivec3(glm::floor(computational)), glm::ivec3(0), grid.dims - 2);
    return cellPosition(grid, cell, computational - glm::dvec3(cell));
}

std::optional<glm::dvec3> solveCellCoordinates(const StructuredGrid& grid, glm::ivec3 cell, glm::dvec3 point) {
    return newton(cornersOf(grid, cell), point);
}

StructuredPointLocator::StructuredPointLocator(const StructuredGrid& grid) : grid_(&grid) {
    const glm::ivec3 cellCounts = grid.dims - 1;
    buckets_ = glm::clamp(cellCounts, glm::ivec3(1), glm::ivec3(kMaxBucketsPerAxis));
    const glm::dvec3 size = glm::max(grid.localUpper - grid.localLower, glm::dvec3(1e-300));
    bucketScale_ = glm::dvec3(buckets_) / size;
    const std::size_t bucketCount = std::size_t(buckets_.x) * buckets_.y * buckets_.z;

    // Two passes over the cells' bounding boxes: count per bucket, then fill (CSR layout).
    std::vector<std::uint32_t> counts(bucketCount + 1, 0);
    auto forEachBucketOf = [&](glm::ivec3 cell, auto&& visit) {
        const CellCorners corners = cornersOf(grid, cell);
        glm::dvec3 lower = corners.corner[0], upper = corners.corner[0];
        for (const glm::dvec3& corner : corners.corner) {
            lower = glm::min(lower, corner);
            upper = glm::max(upper, corner);
        }
        // Trilinear faces bulge at most to the hull of the corners, so the corners' box holds the cell.
        const glm::ivec3 first = glm::clamp(glm::ivec3(glm::floor((lower - grid.localLower) * bucketScale_)),
                                            glm::ivec3(0), buckets_ - 1);
        const glm::ivec3 last = glm::clamp(glm::ivec3(glm::floor((upper - grid.localLower) * bucketScale_)),
                                           glm::ivec3(0), buckets_ - 1);
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x)
                    visit((std::size_t(z) * buckets_.y + y) * buckets_.x + x);
    };
    auto forEachCell = [&](auto&& visit) {
        for (int k = 0; k < cellCounts.z; ++k)
            for (int j = 0; j < cellCounts.y; ++j)
                for (int i = 0; i < cellCounts.x; ++i) visit(glm::ivec3(i, j, k));
    };
    forEachCell([&](glm::ivec3 cell) { forEachBucketOf(cell, [&](std::size_t bucket) { ++counts[bucket + 1]; }); });
    for (std::size_t bucket = 0; bucket < bucketCount; ++bucket) counts[bucket + 1] += counts[bucket];
    bucketStart_ = counts;
    cells_.resize(counts.back());
    std::vector<std::uint32_t> next(counts.begin(), counts.end() - 1);
    forEachCell([&](glm::ivec3 cell) {
        const auto index = std::uint32_t((std::size_t(cell.z) * cellCounts.y + cell.y) * cellCounts.x + cell.x);
        forEachBucketOf(cell, [&](std::size_t bucket) { cells_[next[bucket]++] = index; });
    });
}

std::optional<glm::dvec3> StructuredPointLocator::tryCell(glm::ivec3 cell, glm::dvec3 point) const {
    const auto uvw = solveCellCoordinates(*grid_, cell, point);
    if (!uvw) return std::nullopt;
    if (glm::any(glm::lessThan(*uvw, glm::dvec3(-kInsideTolerance))) ||
        glm::any(glm::greaterThan(*uvw, glm::dvec3(1.0 + kInsideTolerance))))
        return std::nullopt;
    return glm::dvec3(cell) + glm::clamp(*uvw, 0.0, 1.0);
}

std::optional<glm::dvec3> StructuredPointLocator::locate(glm::dvec3 point, glm::ivec3* hint) const {
    if (hint) {
        if (const auto found = tryCell(*hint, point)) return found;
    }
    const glm::dvec3 scaled = (point - grid_->localLower) * bucketScale_;
    // Nodes are float: a point on the boundary may lie a rounding error outside the bounds.
    if (glm::any(glm::lessThan(scaled, glm::dvec3(-1e-4))) ||
        glm::any(glm::greaterThan(scaled, glm::dvec3(buckets_) + 1e-4)))
        return std::nullopt;
    const glm::ivec3 bucket = glm::clamp(glm::ivec3(glm::floor(scaled)), glm::ivec3(0), buckets_ - 1);
    const std::size_t index = (std::size_t(bucket.z) * buckets_.y + bucket.y) * buckets_.x + bucket.x;
    const glm::ivec3 cellCounts = grid_->dims - 1;
    for (std::uint32_t slot = bucketStart_[index]; slot < bucketStart_[index + 1]; ++slot) {
        const std::uint32_t flat = cells_[slot];
        const glm::ivec3 cell(int(flat % std::uint32_t(cellCounts.x)),
                              int((flat / std::uint32_t(cellCounts.x)) % std::uint32_t(cellCounts.y)),
                              int(flat / (std::uint32_t(cellCounts.x) * std::uint32_t(cellCounts.y))));
        if (const auto found = tryCell(cell, point)) {
            if (hint) *hint = cell;
            return found;
        }
    }
    return std::nullopt;
}

}  // namespace tstyles
