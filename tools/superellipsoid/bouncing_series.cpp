// Samples the bouncing super-ellipsoid onto grids (see bouncing_series.h and
// docs/superellipsoid-dataset.md).
#include "bouncing_series.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "bounce_simulation.h"
#include "superellipsoid_shape.h"

namespace superellipsoid {

namespace {

using tstyles::RawTimeStep;
using tstyles::RectilinearGrid;

// Empty voxels kept between the object's non-zero region and the grid's faces, so box borders
// never show and trilinear lookups at the border read exact zeros.
int marginVoxels(int resolution) { return std::max(2, resolution / 16); }

// Isotropic spacing with which a resolution^3 cube just holds the non-zero region plus margin.
double boxSpacing(const SuperEllipsoidShape& shape, int resolution) {
    const glm::dvec3 half = shape.nonZeroHalfExtents();
    const double largestHalf = std::max({half.x, half.y, half.z});
    return 2.0 * largestHalf / double(resolution - 1 - 2 * marginVoxels(resolution));
}

// Written out rather than glm::angleAxis, which leaves -0 in the x and y parts for negative angles.
glm::dquat turnAboutZ(double angle) {
    return glm::dquat(std::cos(0.5 * angle), 0.0, 0.0, std::sin(0.5 * angle));
}

// World half-size of the object's non-zero box when turned about z.
glm::dvec3 turnedHalfExtents(const SuperEllipsoidShape& shape, double angle) {
    const glm::dvec3 half = shape.nonZeroHalfExtents();
    const double c = std::abs(std::cos(angle));
    const double s = std::abs(std::sin(angle));
    return {c * half.x + s * half.y, s * half.x + c * half.y, half.z};
}

std::uint8_t quantize(double density) {
    return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(density, 0.0, 1.0)));
}

std::vector<double> sampleTimes(int steps, double duration) {
    std::vector<double> times;
    for (int i = 0; i < steps; ++i)
        times.push_back(steps == 1 ? 0.0 : duration * double(i) / double(steps - 1));
    return times;
}

// The object-local densities of a box centred on the object; the same for every time-step,
// because the box turns and moves with the object.
std::vector<std::uint8_t> objectBoxValues(const SuperEllipsoidShape& shape,
                                          const RectilinearGrid& grid) {
    std::vector<std::uint8_t> values(grid.voxelCount());
    const glm::dvec3 halfExtent = 0.5 * grid.extent();
    std::size_t index = 0;
    for (int z = 0; z < grid.dims.z; ++z)
        for (int y = 0; y < grid.dims.y; ++y)
            for (int x = 0; x < grid.dims.x; ++x) {
                const glm::dvec3 local = glm::dvec3(x, y, z) * grid.spacing - halfExtent;
                values[index++] = quantize(shape.density(local));
            }
    return values;
}

std::vector<RawTimeStep> partialOverlapSteps(const BouncingSeriesOptions& options,
                                             const SuperEllipsoidShape& shape,
                                             const BounceParameters& bounce,
                                             const Trajectory& trajectory) {
    RectilinearGrid grid;
    grid.dims = glm::ivec3(options.resolution);
    grid.spacing = glm::dvec3(boxSpacing(shape, options.resolution));
    const auto values = objectBoxValues(shape, grid);

    std::vector<RawTimeStep> steps;
    for (double time : sampleTimes(options.steps, bounce.duration)) {
        const BodyState state = sampleTrajectory(trajectory, time);
        RawTimeStep step;
        step.time = time;
        step.grid = grid;
        step.placement.rotation = turnAboutZ(state.angle);
        // Grid-local p maps to origin + rotation * p, and the box's centre must land on the object.
        step.placement.origin = state.centre - step.placement.rotation * (0.5 * grid.extent());
        step.type = tstyles::ValueType::UInt8;
        step.bytes = values;
        steps.push_back(std::move(step));
    }
    return steps;
}

// Where and how fine the common grid is: it covers everything the object touches over the whole
// simulated motion (not just the samples, so it does not depend on --steps).
struct WorldGrid {
    RectilinearGrid grid;
    glm::dvec3 origin{0.0};
};

WorldGrid worldGridAroundPath(const BouncingSeriesOptions& options,
                              const SuperEllipsoidShape& shape, const Trajectory& trajectory) {
    glm::dvec3 lower(std::numeric_limits<double>::infinity());
    glm::dvec3 upper(-std::numeric_limits<double>::infinity());
    for (const BodyState& state : trajectory) {
        const glm::dvec3 half = turnedHalfExtents(shape, state.angle);
        lower = glm::min(lower, state.centre - half);
        upper = glm::max(upper, state.centre + half);
    }
    const glm::dvec3 reach = upper - lower;

    // The box spacing where it fits; coarser where the path would need more than
    // (4R, 2R, R) samples, which keeps the default at most 256 x 128 x 64.
    const int margin = marginVoxels(options.resolution);
    const glm::dvec3 cap = glm::dvec3(4.0, 2.0, 1.0) * double(options.resolution);
    const glm::dvec3 fitting = reach / (cap - 1.0 - 2.0 * margin);
    const double spacing =
        std::max({boxSpacing(shape, options.resolution), fitting.x, fitting.y, fitting.z});

    WorldGrid world;
    world.grid.spacing = glm::dvec3(spacing);
    // The small tolerance stops rounding from adding a sample beyond the cap.
    world.grid.dims = glm::ivec3(glm::ceil(reach / spacing - 1e-9)) + 2 * margin + 1;
    world.origin = 0.5 * (lower + upper) - 0.5 * world.grid.extent();
    return world;
}

// Densities of one time-step on the common grid: each voxel's world position is taken into the
// object's frame at that time. Only voxels inside the turned non-zero box need the function.
std::vector<std::uint8_t> worldGridValues(const SuperEllipsoidShape& shape, const WorldGrid& world,
                                          const BodyState& state) {
    const RectilinearGrid& grid = world.grid;
    std::vector<std::uint8_t> values(grid.voxelCount(), 0);
    const glm::dvec3 half = turnedHalfExtents(shape, state.angle);
    const glm::ivec3 first =
        glm::max(glm::ivec3(glm::floor((state.centre - half - world.origin) / grid.spacing)), 0);
    const glm::ivec3 last = glm::min(
        glm::ivec3(glm::ceil((state.centre + half - world.origin) / grid.spacing)), grid.dims - 1);
    const glm::dquat worldToObject = glm::conjugate(turnAboutZ(state.angle));

    for (int z = first.z; z <= last.z; ++z)
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x) {
                const glm::dvec3 worldPosition = world.origin + glm::dvec3(x, y, z) * grid.spacing;
                const glm::dvec3 local = worldToObject * (worldPosition - state.centre);
                const std::size_t index =
                    (std::size_t(z) * std::size_t(grid.dims.y) + std::size_t(y)) *
                        std::size_t(grid.dims.x) +
                    std::size_t(x);
                values[index] = quantize(shape.density(local));
            }
    return values;
}

std::vector<RawTimeStep> alignedSteps(const BouncingSeriesOptions& options,
                                      const SuperEllipsoidShape& shape,
                                      const BounceParameters& bounce,
                                      const Trajectory& trajectory) {
    const WorldGrid world = worldGridAroundPath(options, shape, trajectory);
    std::vector<RawTimeStep> steps;
    for (double time : sampleTimes(options.steps, bounce.duration)) {
        RawTimeStep step;
        step.time = time;
        step.grid = world.grid;
        step.placement.origin = world.origin;
        step.type = tstyles::ValueType::UInt8;
        step.bytes = worldGridValues(shape, world, sampleTrajectory(trajectory, time));
        steps.push_back(std::move(step));
    }
    return steps;
}

}  // namespace

tstyles::RawSeries buildBouncingSeries(const BouncingSeriesOptions& options) {
    const SuperEllipsoidShape shape;
    BounceParameters bounce;
    bounce.duration = options.duration;
    const Trajectory trajectory = simulateBounce(bounce, shape);

    tstyles::RawSeries series;
    series.valueRange = {0.0, 255.0};
    if (options.aligned) {
        series.name = "bouncing super-ellipsoid (fully aligned)";
        series.steps = alignedSteps(options, shape, bounce, trajectory);
    } else {
        series.name = "bouncing super-ellipsoid (partial overlap)";
        series.steps = partialOverlapSteps(options, shape, bounce, trajectory);
    }
    return series;
}

}  // namespace superellipsoid
