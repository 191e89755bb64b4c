// Trilinear density lookups in a time-step's grid (box, structured grid or beam fan), in world coordinates.
#include "tstyles/data/density_sampling.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "tstyles/data/beam_geometry.h"
#include "tstyles/data/grid_axes.h"
#include "tstyles/data/structured_point_location.h"

namespace tstyles {
namespace {

constexpr double kBoundaryTolerance = 1e-3;  // in voxels

// Trilinear at `voxel` (inside [0, dims - 1]), like the renderer: the mix of the corners that have
// data, divided by their weight; no data where the corners with data weigh less than half.
double interpolateAtVoxel(const TimeStep& step, const glm::ivec3& dims, glm::dvec3 voxel) {
    const glm::ivec3 lower = glm::min(glm::ivec3(glm::floor(voxel)), glm::max(dims - 2, 0));
    const glm::dvec3 t = voxel - glm::dvec3(lower);
    double weightedDensity = 0.0;
    double validWeight = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 offset((corner & 1) ? 1 : 0, (corner & 2) ? 1 : 0, (corner & 4) ? 1 : 0);
        const glm::ivec3 node = glm::min(lower + offset, dims - 1);
        const glm::dvec3 weights = glm::mix(1.0 - t, t, glm::dvec3(offset));
        const double weight = weights.x * weights.y * weights.z;
        const std::size_t index =
            (std::size_t(node.z) * std::size_t(dims.y) + std::size_t(node.y)) * std::size_t(dims.x) +
            std::size_t(node.x);
        const float density = step.density[index];
        if (isMissing(density)) continue;
        weightedDensity += weight * double(density);
        validWeight += weight;
    }
    if (validWeight < 0.5) return double(missingDensity());
    return weightedDensity / validWeight;
}

glm::dvec3 localPosition(const TimeStep& step, const glm::dvec3& world) {
    // Undo the placement: origin, then rotation.
    return glm::conjugate(step.placement.rotation) * (world - step.placement.origin);
}

std::optional<double> sampleStructured(const TimeStep& step, const StructuredPointLocator& locator,
                                       const glm::dvec3& world) {
    const auto computational = locator.locate(localPosition(step, world));
    if (!computational) return std::nullopt;
    return interpolateAtVoxel(step, step.dims(), *computational);
}

// Fractional voxel coordinates of a grid-local position, unclamped; none outside a beam fan.
std::optional<glm::dvec3> voxelOf(const TimeStep& step, const glm::dvec3& local) {
    if (step.isBeam()) return beamVoxel(step.beam(), local);
    return localToVoxel(step.rectilinear(), local);
}

}  // namespace

std::optional<double> sampleDensity(const TimeStep& step, const glm::dvec3& world) {
    if (step.density.size() != gridVoxelCount(step.grid) || step.density.empty()) return std::nullopt;
    if (const StructuredGrid* structured = step.structured()) {
        // Exact point location (no inverse map): a locator per call is fine for a pick.
        return sampleStructured(step, StructuredPointLocator(*structured), world);
    }
    const glm::ivec3 dims = step.dims();
    const std::optional<glm::dvec3> voxelOrNone = voxelOf(step, localPosition(step, world));
    if (!voxelOrNone) return std::nullopt;
    glm::dvec3 voxel = *voxelOrNone;
    const glm::dvec3 last = glm::dvec3(dims - 1);
    for (int axis = 0; axis < 3; ++axis) {
        if (voxel[axis] < -kBoundaryTolerance || voxel[axis] > last[axis] + kBoundaryTolerance) return std::nullopt;
        voxel[axis] = std::clamp(voxel[axis], 0.0, last[axis]);
    }
    return interpolateAtVoxel(step, dims, voxel);
}

TemporalProfiler::TemporalProfiler(const Series& series) : series_(series) {
    for (const TimeStep& step : series.steps) {
        const StructuredGrid* structured = step.structured();
        if (!structured || step.density.size() != structured->voxelCount()) {
            locatorOfStep_.push_back(nullptr);
            continue;
        }
        auto known = std::find_if(locators_.begin(), locators_.end(), [structured](const auto& locator) {
            return locator->grid().nodes == structured->nodes;
        });
        if (known == locators_.end()) {
            locators_.push_back(std::make_unique<StructuredPointLocator>(*structured));
            known = locators_.end() - 1;
        }
        locatorOfStep_.push_back(known->get());
    }
}

TemporalProfiler::~TemporalProfiler() = default;

std::vector<std::optional<double>> TemporalProfiler::profile(const glm::dvec3& world) const {
    std::vector<std::optional<double>> profile;
    profile.reserve(series_.size());
    for (std::size_t index = 0; index < series_.steps.size(); ++index) {
        const TimeStep& step = series_.steps[index];
        const StructuredPointLocator* locator = locatorOfStep_[index];
        profile.push_back(locator ? sampleStructured(step, *locator, world) : sampleDensity(step, world));
    }
    return profile;
}

std::vector<std::optional<double>> temporalProfile(const Series& series, const glm::dvec3& world) {
    return TemporalProfiler(series).profile(world);
}

}  // namespace tstyles
