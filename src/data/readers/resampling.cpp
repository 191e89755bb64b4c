// Trilinear resampling that keeps missing values missing instead of blending them into data.
#include "resampling.h"

#include <array>
#include <cmath>

#include "tstyles/data/grid_axes.h"

namespace tstyles {
namespace {

// Where node `index` of `toCount` nodes falls among `fromCount` nodes spanning the same extent.
double sourceIndex(int index, int toCount, int fromCount) {
    return double(index) * double(fromCount - 1) / double(toCount - 1);
}

struct AxisTap {
    int lower = 0;
    double weight = 0.0;  // of the upper neighbour
};

std::vector<AxisTap> axisTaps(int toCount, int fromCount) {
    std::vector<AxisTap> taps(static_cast<std::size_t>(toCount));
    for (int index = 0; index < toCount; ++index) {
        const double source = sourceIndex(index, toCount, fromCount);
        const int lower = std::min(int(std::floor(source)), fromCount - 2);
        taps[std::size_t(index)] = {lower, source - double(lower)};
    }
    return taps;
}

}  // namespace

RectilinearGrid resampledGrid(const RectilinearGrid& grid, const glm::ivec3& dims) {
    RectilinearGrid result;
    result.dims = dims;
    for (int axis = 0; axis < 3; ++axis) {
        result.spacing[axis] = grid.extent()[axis] / double(dims[axis] - 1);
        if (!grid.isUneven(axis)) continue;
        std::vector<double>& positions = result.axisPositions[std::size_t(axis)];
        for (int index = 0; index < dims[axis]; ++index)
            positions.push_back(nodePosition(grid, axis, sourceIndex(index, dims[axis], grid.dims[axis])));
        positions.front() = 0.0;
    }
    return result;
}

std::vector<float> resampleValues(const std::vector<float>& values, const RectilinearGrid& from,
                                  const glm::ivec3& toDims) {
    const std::array<std::vector<AxisTap>, 3> taps{axisTaps(toDims.x, from.dims.x), axisTaps(toDims.y, from.dims.y),
                                                   axisTaps(toDims.z, from.dims.z)};
    const std::size_t nx = std::size_t(from.dims.x);
    const std::size_t nxy = nx * std::size_t(from.dims.y);
    std::vector<float> result;
    result.reserve(std::size_t(toDims.x) * std::size_t(toDims.y) * std::size_t(toDims.z));
    for (const AxisTap& z : taps[2])
        for (const AxisTap& y : taps[1])
            for (const AxisTap& x : taps[0]) {
                double sum = 0.0;
                double weightSum = 0.0;
                for (int corner = 0; corner < 8; ++corner) {
                    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
                    const double weight = (dx ? x.weight : 1.0 - x.weight) * (dy ? y.weight : 1.0 - y.weight) *
                                          (dz ? z.weight : 1.0 - z.weight);
                    if (weight == 0.0) continue;
                    const float value = values[std::size_t(x.lower + dx) + nx * std::size_t(y.lower + dy) +
                                               nxy * std::size_t(z.lower + dz)];
                    if (isMissing(value)) continue;
                    sum += weight * double(value);
                    weightSum += weight;
                }
                // Missing when most of the weight is missing: the boundary of a missing region stays where it
                // was instead of data bleeding into it or it eating into the data.
                result.push_back(weightSum >= 0.5 ? float(sum / weightSum) : missingDensity());
            }
    return result;
}

}  // namespace tstyles
