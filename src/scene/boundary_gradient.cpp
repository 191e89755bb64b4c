// The value gradient at the visible places of a series (boundary_gradient.h).
#include "tstyles/scene/boundary_gradient.h"

#include <algorithm>
#include <cmath>

#include "tstyles/scene/temporal_change.h"

namespace tstyles {
namespace {

constexpr double kBoundaryPercentile = 0.99;

// The grid-local position of node `index` along `axis`.
double nodePosition(const RectilinearGrid& grid, int axis, int index) {
    return grid.isUneven(axis) ? grid.axisPositions[std::size_t(axis)][std::size_t(index)]
                               : double(index) * grid.spacing[axis];
}

}  // namespace

void addGradientMagnitudes(const TimeStep& step, const Stf& stf, std::size_t stride, std::vector<double>& magnitudes) {
    const auto* grid = std::get_if<RectilinearGrid>(&step.grid);
    if (grid == nullptr || step.density.size() != grid->voxelCount()) return;
    const glm::ivec3 dims = grid->dims;
    const auto at = [&](glm::ivec3 node) {
        return step.density[(std::size_t(node.z) * std::size_t(dims.y) + std::size_t(node.y)) * std::size_t(dims.x) +
                            std::size_t(node.x)];
    };
    for (std::size_t index = 0; index < step.density.size(); index += std::max<std::size_t>(1, stride)) {
        const float centre = step.density[index];
        if (isMissing(centre) || stf.curve.evaluate(centre).opacity <= 0.0) continue;
        const glm::ivec3 node(int(index % std::size_t(dims.x)), int(index / std::size_t(dims.x) % std::size_t(dims.y)),
                              int(index / (std::size_t(dims.x) * std::size_t(dims.y))));
        double squared = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            glm::ivec3 lower = node, upper = node;
            lower[axis] = std::max(0, node[axis] - 1);
            upper[axis] = std::min(dims[axis] - 1, node[axis] + 1);
            if (isMissing(at(lower))) lower = node;
            if (isMissing(at(upper))) upper = node;
            const double span = nodePosition(*grid, axis, upper[axis]) - nodePosition(*grid, axis, lower[axis]);
            if (span > 0.0) {
                const double slope = (double(at(upper)) - double(at(lower))) / span;
                squared += slope * slope;
            }
        }
        magnitudes.push_back(std::sqrt(squared));
    }
}

double boundaryGradientOf(std::vector<double> magnitudes) {
    if (magnitudes.empty()) return 0.0;
    const auto at = magnitudes.begin() + std::ptrdiff_t(kBoundaryPercentile * double(magnitudes.size() - 1));
    std::nth_element(magnitudes.begin(), at, magnitudes.end());
    return *at;
}

std::vector<double> gradientMagnitudes(const Series& series, const Stf& stf) {
    std::vector<double> magnitudes;
    if (!series.steps.empty()) addGradientMagnitudes(series.steps.front(), stf, changeNodeStride(series), magnitudes);
    return magnitudes;
}

}  // namespace tstyles
