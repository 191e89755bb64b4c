// Trilinear density lookups in a time-step's grid (box or beam fan), in world coordinates.
#include "tstyles/data/density_sampling.h"

#include "tstyles/data/beam_geometry.h"

#include <algorithm>
#include <cmath>

namespace tstyles {
namespace {

constexpr double kBoundaryTolerance = 1e-3;  // in voxels

double valueAt(const TimeStep& step, const glm::ivec3& dims, int x, int y, int z) {
    const std::size_t index =
        (std::size_t(z) * std::size_t(dims.y) + std::size_t(y)) * std::size_t(dims.x) + std::size_t(x);
    return double(step.density[index]);
}

// Fractional voxel coordinates of a grid-local position, unclamped; none outside a beam fan.
std::optional<glm::dvec3> voxelOf(const TimeStep& step, const glm::dvec3& local) {
    if (step.isBeam()) return beamVoxel(step.beam(), local);
    return local / step.rectilinear().spacing;
}

}  // namespace

std::optional<double> sampleDensity(const TimeStep& step, const glm::dvec3& world) {
    const glm::ivec3 dims = gridDims(step.grid);
    if (step.density.size() != gridVoxelCount(step.grid) || step.density.empty()) return std::nullopt;
    // Grid-local position: undo the placement (origin, then rotation), then count voxels.
    const glm::dvec3 local = glm::conjugate(step.placement.rotation) * (world - step.placement.origin);
    const std::optional<glm::dvec3> voxelOrNone = voxelOf(step, local);
    if (!voxelOrNone) return std::nullopt;
    glm::dvec3 voxel = *voxelOrNone;
    const glm::dvec3 last = glm::dvec3(dims - 1);
    for (int axis = 0; axis < 3; ++axis) {
        if (voxel[axis] < -kBoundaryTolerance || voxel[axis] > last[axis] + kBoundaryTolerance) return std::nullopt;
        voxel[axis] = std::clamp(voxel[axis], 0.0, last[axis]);
    }
    const glm::ivec3 lower = glm::min(glm::ivec3(glm::floor(voxel)), glm::max(dims - 2, 0));
    const glm::ivec3 upper = glm::min(lower + 1, dims - 1);
    const glm::dvec3 t = voxel - glm::dvec3(lower);
    auto along = [&](int y, int z) {
        return glm::mix(valueAt(step, dims, lower.x, y, z), valueAt(step, dims, upper.x, y, z), t.x);
    };
    const double front = glm::mix(along(lower.y, lower.z), along(upper.y, lower.z), t.y);
    const double back = glm::mix(along(lower.y, upper.z), along(upper.y, upper.z), t.y);
    return glm::mix(front, back, t.z);
}

std::vector<std::optional<double>> temporalProfile(const Series& series, const glm::dvec3& world) {
    std::vector<std::optional<double>> profile;
    profile.reserve(series.size());
    for (const TimeStep& step : series.steps) profile.push_back(sampleDensity(step, world));
    return profile;
}

}  // namespace tstyles
