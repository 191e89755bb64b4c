// Sampling, quantising and placing the hurricane: grid x east, y north, z up; the placement turns
// z to world up (y) and y to world -z, so the default camera looks at the storm from the south.
#include "hurricane_series.h"

#include <cmath>
#include <stdexcept>

#include <glm/gtc/quaternion.hpp>

#include "hurricane_model.h"

namespace hurricane {

std::vector<double> levelHeights(int levels) {
    if (levels < 2) throw std::invalid_argument("levelHeights: need at least two levels");
    // Gap k is g0 + c * k; the lowest is a third of the topmost.
    const int gaps = levels - 1;
    const double lowest = 2.0 * kTopHeight / (double(gaps) * 4.0);
    const double growth = (kTopHeight - lowest * gaps) / (0.5 * gaps * (gaps - 1));
    std::vector<double> heights{0.0};
    for (int gap = 0; gap < gaps; ++gap) heights.push_back(heights.back() + lowest + growth * gap);
    heights.back() = kTopHeight;  // exact, whatever the rounding on the way
    return heights;
}

tstyles::RawSeries buildHurricaneSeries(const HurricaneSeriesOptions& options) {
    if (options.steps < 1) throw std::invalid_argument("buildHurricaneSeries: need at least one time-step");
    tstyles::RectilinearGrid grid;
    grid.dims = options.dims;
    grid.spacing = {kDomainSize / (grid.dims.x - 1), kDomainSize / (grid.dims.y - 1), 1.0};
    grid.axisPositions[2] = levelHeights(grid.dims.z);

    tstyles::Placement placement;
    // Grid z (height) to world +y, grid y (north) to world -z: a -90 degree turn about x.
    placement.rotation = glm::angleAxis(glm::radians(-90.0), glm::dvec3(1.0, 0.0, 0.0));
    placement.origin = {0.0, 0.0, kDomainSize};

    tstyles::RawSeries series;
    series.name = "synthetic hurricane (cloud water)";
    series.valueRange = {0.0, 254.0};
    series.missingValue = kLandMarker;
    for (int index = 0; index < options.steps; ++index) {
        const double hours = options.steps > 1 ? kDurationHours * index / (options.steps - 1) : 0.0;
        tstyles::RawTimeStep step;
        step.time = hours;
        step.grid = grid;
        step.placement = placement;
        step.type = tstyles::ValueType::UInt8;
        step.bytes.reserve(grid.voxelCount());
        for (int z = 0; z < grid.dims.z; ++z) {
            const double height = grid.axisPositions[2][std::size_t(z)];
            for (int y = 0; y < grid.dims.y; ++y)
                for (int x = 0; x < grid.dims.x; ++x) {
                    const glm::dvec2 ground(x * grid.spacing.x, y * grid.spacing.y);
                    if (height < terrainHeight(ground)) {
                        step.bytes.push_back(std::uint8_t(kLandMarker));
                        continue;
                    }
                    const double water = cloudWater({ground, height}, hours);
                    step.bytes.push_back(std::uint8_t(std::lround(water * 254.0)));
                }
        }
        series.steps.push_back(std::move(step));
    }
    return series;
}

}  // namespace hurricane
