// Trilinear density lookups in a time-step's rectilinear grid, in world coordinates.
#include "tstyles/data/density_sampling.h"

#include <algorithm>
#include <cmath>

#include "tstyles/data/grid_axes.h"

namespace tstyles {
namespace {

constexpr double kBoundaryTolerance = 1e-3;  // in voxels

}  // namespace

std::optional<double> sampleDensity(const TimeStep& step, const glm::dvec3& world) {
    const RectilinearGrid& grid = step.rectilinear();
    if (step.density.size() != grid.voxelCount() || grid.voxelCount() == 0) return std::nullopt;
    // Grid-local position: undo the placement (origin, then rotation), then count voxels.
    const glm::dvec3 local = glm::conjugate(step.placement.rotation) * (world - step.placement.origin);
    glm::dvec3 voxel = localToVoxel(grid, local);
    const glm::dvec3 last = glm::dvec3(grid.dims - 1);
    for (int axis = 0; axis < 3; ++axis) {
        if (voxel[axis] < -kBoundaryTolerance || voxel[axis] > last[axis] + kBoundaryTolerance) return std::nullopt;
        voxel[axis] = std::clamp(voxel[axis], 0.0, last[axis]);
    }
    const glm::ivec3 lower = glm::min(glm::ivec3(glm::floor(voxel)), glm::max(grid.dims - 2, 0));
    const glm::dvec3 t = voxel - glm::dvec3(lower);
    // Like the renderer: the trilinear mix of the corners that have data, divided by their weight;
    // no data where the corners with data weigh less than half.
    double weightedDensity = 0.0;
    double validWeight = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 offset((corner & 1) ? 1 : 0, (corner & 2) ? 1 : 0, (corner & 4) ? 1 : 0);
        const glm::ivec3 node = glm::min(lower + offset, grid.dims - 1);
        const glm::dvec3 weights = glm::mix(1.0 - t, t, glm::dvec3(offset));
        const double weight = weights.x * weights.y * weights.z;
        const std::size_t index =
            (std::size_t(node.z) * std::size_t(grid.dims.y) + std::size_t(node.y)) * std::size_t(grid.dims.x) +
            std::size_t(node.x);
        const float density = step.density[index];
        if (isMissing(density)) continue;
        weightedDensity += weight * double(density);
        validWeight += weight;
    }
    if (validWeight < 0.5) return double(missingDensity());
    return weightedDensity / validWeight;
}

std::vector<std::optional<double>> temporalProfile(const Series& series, const glm::dvec3& world) {
    std::vector<std::optional<double>> profile;
    profile.reserve(series.size());
    for (const TimeStep& step : series.steps) profile.push_back(sampleDensity(step, world));
    return profile;
}

}  // namespace tstyles
