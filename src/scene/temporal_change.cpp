// The changes over time of a series' visible places (temporal_change.h).
#include "tstyles/scene/temporal_change.h"

#include <algorithm>

#include "tstyles/data/density_sampling.h"
#include "tstyles/scene/visible_bounds.h"

namespace tstyles {
namespace {

// The percentile of the visible voxels' temporal change that the gradient TSTF's range reaches.
constexpr double kChangePercentile = 0.99;
// A lattice of this many points per axis samples the change of series whose time-steps do not share
// one grid.
constexpr int kChangeLattice = 32;
// A shared grid's changes are taken at this many nodes at most.
constexpr std::size_t kMostChangedNodes = std::size_t(1) << 20;

}  // namespace

bool sharesOneGrid(const Series& series) {
    if (series.steps.empty()) return false;
    const TimeStep& first = series.steps.front();
    if (!std::holds_alternative<RectilinearGrid>(first.grid)) return false;
    return std::all_of(series.steps.begin(), series.steps.end(), [&](const TimeStep& step) {
        return std::holds_alternative<RectilinearGrid>(step.grid) && step.dims() == first.dims() &&
               step.placement == first.placement;
    });
}

std::size_t changeNodeStride(const Series& series) {
    const std::size_t nodes = series.steps.empty() ? 0 : gridVoxelCount(series.steps.front().grid);
    return std::max<std::size_t>(1, nodes / kMostChangedNodes);
}

std::vector<glm::dvec3> changeLatticePoints(const Bounds& visible) {
    std::vector<glm::dvec3> points;
    points.reserve(std::size_t(kChangeLattice) * kChangeLattice * kChangeLattice);
    for (int k = 0; k < kChangeLattice; ++k)
        for (int j = 0; j < kChangeLattice; ++j)
            for (int i = 0; i < kChangeLattice; ++i)
                points.push_back(visible.lower + (glm::dvec3(i, j, k) + 0.5) / double(kChangeLattice) * visible.size());
    return points;
}

void addChange(const std::vector<double>& densities, const Stf& stf, std::vector<double>& changes) {
    double lowest = 2.0;
    double highest = -1.0;
    bool visible = false;
    int valid = 0;
    for (double density : densities) {
        if (isMissing(float(density))) continue;
        ++valid;
        lowest = std::min(lowest, density);
        highest = std::max(highest, density);
        visible = visible || stf.curve.evaluate(density).opacity > 0.0;
    }
    if (visible && valid >= 2) changes.push_back(highest - lowest);
}

double typicalOf(std::vector<double> changes) {
    if (changes.empty()) return 1.0;
    const auto at = changes.begin() + std::ptrdiff_t(kChangePercentile * double(changes.size() - 1));
    std::nth_element(changes.begin(), at, changes.end());
    return std::clamp(*at, 1e-3, 1.0);
}

std::vector<double> temporalChanges(const Series& series, const Stf& stf) {
    std::vector<double> changes;
    if (series.size() < 2) return changes;
    std::vector<double> densities(series.size());
    if (sharesOneGrid(series)) {
        const std::size_t voxels = series.steps.front().density.size();
        const std::size_t stride = changeNodeStride(series);
        for (std::size_t voxel = 0; voxel < voxels; voxel += stride) {
            for (std::size_t step = 0; step < series.size(); ++step)
                densities[step] = series.steps[step].density[voxel];
            addChange(densities, stf, changes);
        }
        return changes;
    }
    const TemporalProfiler profiler(series);
    for (const glm::dvec3& at : changeLatticePoints(visibleBounds(series, stf))) {
        densities.clear();
        for (const auto& density : profiler.profile(at))
            if (density) densities.push_back(*density);
        addChange(densities, stf, changes);
    }
    return changes;
}

}  // namespace tstyles
