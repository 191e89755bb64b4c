// Resampling a whole series to a coarser resolution for a GPU memory budget.
#include "tstyles/data/coarser_series.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "readers/resampling.h"

namespace tstyles {
namespace {

// The nearest source sample of each target sample, per axis (same extent, nodes on both ends).
std::vector<int> nearestSources(int toCount, int fromCount) {
    std::vector<int> nearest;
    for (int index = 0; index < toCount; ++index)
        nearest.push_back(int(std::lround(double(index) * double(fromCount - 1) / double(toCount - 1))));
    return nearest;
}

std::vector<std::uint8_t> nearestMask(const std::vector<std::uint8_t>& mask, glm::ivec3 from, glm::ivec3 to) {
    const std::vector<int> xs = nearestSources(to.x, from.x), ys = nearestSources(to.y, from.y),
                           zs = nearestSources(to.z, from.z);
    std::vector<std::uint8_t> result;
    result.reserve(std::size_t(to.x) * std::size_t(to.y) * std::size_t(to.z));
    for (int z : zs)
        for (int y : ys)
            for (int x : xs)
                result.push_back(mask[std::size_t(x) + std::size_t(from.x) * (std::size_t(y) + std::size_t(from.y) * std::size_t(z))]);
    return result;
}

}  // namespace

bool canCoarsen(const Series& series) {
    return std::all_of(series.steps.begin(), series.steps.end(),
                       [](const TimeStep& step) { return std::holds_alternative<RectilinearGrid>(step.grid); });
}

glm::ivec3 coarserDims(glm::ivec3 dims, double scale) {
    const glm::ivec3 scaled(glm::floor(glm::dvec3(dims) / scale));
    return glm::clamp(scaled, glm::ivec3(2), glm::max(dims, glm::ivec3(2)));
}

Series coarserSeries(const Series& series, double scale) {
    if (!canCoarsen(series)) throw std::logic_error("coarserSeries: only rectilinear time-steps can be resampled");
    Series result = withoutTimeSteps(series);
    for (const TimeStep& step : series.steps) {
        const RectilinearGrid& grid = step.rectilinear();
        const glm::ivec3 dims = coarserDims(grid.dims, scale);
        TimeStep coarse = withoutValues(step);
        if (dims == grid.dims) {
            coarse.density = step.density;
            coarse.mask = step.mask;
        } else {
            coarse.grid = resampledGrid(grid, dims);
            coarse.density = resampleValues(step.density, grid, dims);
            if (step.mask) coarse.mask = nearestMask(*step.mask, grid.dims, dims);
        }
        result.steps.push_back(std::move(coarse));
    }
    return result;
}

}  // namespace tstyles
