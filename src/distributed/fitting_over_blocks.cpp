// The value-dependent parts of a scene, fitted over the processes' blocks (fitting_over_blocks.h).
#include "tstyles/distributed/fitting_over_blocks.h"

#include <cmath>
#include <limits>

#include "tstyles/data/beam_geometry.h"
#include "tstyles/data/density_sampling.h"
#include "tstyles/data/grid_axes.h"
#include "tstyles/scene/automatic_opacity.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/boundary_gradient.h"
#include "tstyles/scene/temporal_change.h"
#include "tstyles/scene/visible_bounds.h"

namespace tstyles {
namespace {

// A node's grid-local position in a rectilinear or beam grid (the time-steps that blocks cut).
glm::dvec3 nodeLocalPosition(const Grid& grid, const glm::ivec3& node) {
    if (const auto* beam = std::get_if<BeamGrid>(&grid)) return beamSamplePosition(*beam, node.x, node.y, node.z);
    return voxelToLocal(std::get<RectilinearGrid>(grid), glm::dvec3(node));
}

// Which process counts a node of a time-step that every process holds in part: the owner of its
// world position, from the whole grid (the outline's), so that every process computes it alike.
class NodeOwnership {
public:
    NodeOwnership(const BlockDecomposition& blocks, int rank, const TimeStep& whole)
        : blocks_(blocks), rank_(rank), grid_(whole.grid), toWorld_(whole.placement.gridToWorld()) {}

    bool ownsNode(const glm::ivec3& node) const {
        const glm::dvec3 world(toWorld_ * glm::dvec4(nodeLocalPosition(grid_, node), 1.0));
        return blocks_.ownerOf(world) == rank_;
    }

private:
    const BlockDecomposition& blocks_;
    int rank_;
    const Grid& grid_;
    glm::dmat4 toWorld_;
};

// Calls visit(localIndex) for the nodes of a cut time-step whose linear index in the whole
// grid is a multiple of `stride` and whose position this process owns.
template <typename Visit>
void forOwnedNodes(const BlockDecomposition& blocks, int rank, const TimeStep& whole, const NodeBlock& nodes,
                   std::size_t stride, Visit visit) {
    const NodeOwnership ownership(blocks, rank, whole);
    const glm::ivec3 dims = whole.dims();
    std::size_t local = 0;
    for (int z = 0; z < nodes.count.z; ++z)
        for (int y = 0; y < nodes.count.y; ++y)
            for (int x = 0; x < nodes.count.x; ++x, ++local) {
                const glm::ivec3 node = nodes.first + glm::ivec3(x, y, z);
                const std::size_t linear =
                    (std::size_t(node.z) * std::size_t(dims.y) + std::size_t(node.y)) * std::size_t(dims.x) +
                    std::size_t(node.x);
                if (linear % stride == 0 && ownership.ownsNode(node)) visit(local);
            }
}

// This process's counts of the density histogram that automaticOpacityWindow takes of the whole
// series: its owned nodes among those counted; a time-step kept whole (structured) is counted by
// process 0.
std::vector<double> histogramShare(const MpiSession& mpi, const BlockDecomposition& blocks, const Series& outline,
                                   const BlockOfSeries& block) {
    std::vector<double> counts(kOpacityHistogramBins, 0.0);
    const std::size_t stride = opacityHistogramStride(outline);
    auto count = [&](float density) {
        if (!isMissing(density)) counts[std::size_t(opacityHistogramBin(density))] += 1.0;
    };
    for (std::size_t index = 0; index < block.series.steps.size(); ++index) {
        const std::vector<float>& density = block.series.steps[index].density;
        if (const auto& nodes = block.nodes.at(index))
            forOwnedNodes(blocks, mpi.rank(), outline.steps[index], *nodes, stride,
                          [&](std::size_t local) { count(density[local]); });
        else if (mpi.isFirst())
            for (std::size_t local = 0; local < density.size(); local += stride) count(density[local]);
    }
    return counts;
}

// The visible node boxes of every time-step in the whole grids' indices, over every process's block.
std::vector<NodeIndexBox> visibleBoxesOverBlocks(const MpiSession& mpi, const Stf& stf, const BlockOfSeries& block) {
    std::vector<NodeIndexBox> boxes;
    mpi.together("finding the visible part of this process's block",
                 [&] { boxes = visibleNodeBoxes(block.series, stf); });
    // Merged as minima and maxima; an empty box (lower INT_MAX, upper INT_MIN) takes no part.
    std::vector<double> lower;
    std::vector<double> upper;
    for (std::size_t index = 0; index < boxes.size(); ++index) {
        NodeIndexBox box = boxes[index];
        if (!box.empty() && block.nodes[index]) {
            box.lower += block.nodes[index]->first;
            box.upper += block.nodes[index]->first;
        }
        for (int axis = 0; axis < 3; ++axis) {
            lower.push_back(double(box.lower[axis]));
            upper.push_back(double(box.upper[axis]));
        }
    }
    lower = mpi.minimum(std::move(lower));
    upper = mpi.maximum(std::move(upper));
    for (std::size_t index = 0; index < boxes.size(); ++index)
        for (int axis = 0; axis < 3; ++axis) {
            boxes[index].lower[axis] = int(lower[3 * index + std::size_t(axis)]);
            boxes[index].upper[axis] = int(upper[3 * index + std::size_t(axis)]);
        }
    return boxes;
}

// This process's share of temporalChanges: the owned nodes of a shared grid among those taken, or
// the owned points of the lattice over the visible bounds.
PlaceChanges changeShare(const MpiSession& mpi, const BlockDecomposition& blocks, const Stf& stf,
                         const Series& outline, const BlockOfSeries& block, const Bounds& visible) {
    PlaceChanges changes;
    if (outline.size() < 2) return changes;
    std::vector<double> densities(outline.size());
    if (sharesOneGrid(outline)) {
        // One grid and placement: every time-step holds the same nodes of it.
        forOwnedNodes(blocks, mpi.rank(), outline.steps.front(), *block.nodes.front(), changeNodeStride(outline),
                      [&](std::size_t local) {
                          for (std::size_t step = 0; step < outline.size(); ++step)
                              densities[step] = block.series.steps[step].density[local];
                          addChange(densities, stf, changes);
                      });
        return changes;
    }
    const TemporalProfiler profiler(block.series);
    for (const glm::dvec3& at : changeLatticePoints(visible)) {
        if (blocks.ownerOf(at) != mpi.rank()) continue;
        densities.clear();
        for (const auto& density : profiler.profile(at))
            if (density) densities.push_back(*density);
        addChange(densities, stf, changes);
    }
    return changes;
}

}  // namespace

bool fittingReadsValues(const Scene& scene, bool automaticOpacity) {
    const bool fitsUnchanged = scene.compositorOptions.unchanged && scene.compositorOptions.unchanged->automatic;
    return automaticOpacity || scene.gradientTstf.automaticRange || fitsUnchanged ||
           scene.camera.framing == Framing::Visible;
}

SceneFittedOverBlocks fitOverBlocks(const MpiSession& mpi, const BlockDecomposition& blocks, Scene scene,
                                    bool automaticOpacity, const Series& displayOutline, const BlockOfSeries& block,
                                    const Bounds& framedOutline) {
    if (automaticOpacity) {
        std::vector<double> counts;
        mpi.together("counting the densities of this process's block",
                     [&] { counts = histogramShare(mpi, blocks, displayOutline, block); });
        counts = mpi.sum(std::move(counts));
        scene.stf.curve.opacity =
            opacityNodes(opacityWindowOf(std::move(counts), averageVoxelsPerStep(displayOutline)));
    }
    const bool fitsUnchanged = scene.compositorOptions.unchanged && scene.compositorOptions.unchanged->automatic;
    const bool fitsChanges = scene.gradientTstf.automaticRange || fitsUnchanged;
    const bool latticeChanges = fitsChanges && displayOutline.size() >= 2 && !sharesOneGrid(displayOutline);
    Bounds visible = displayOutline.worldBounds();
    if (scene.camera.framing == Framing::Visible || latticeChanges)
        visible = boundsOfVisibleNodes(displayOutline, visibleBoxesOverBlocks(mpi, scene.stf, block));
    if (fitsChanges) {
        PlaceChanges share;
        mpi.together("taking the changes over time in this process's block",
                     [&] { share = changeShare(mpi, blocks, scene.stf, displayOutline, block, visible); });
        const PlaceChanges places{mpi.gathered(share.changes), mpi.gathered(share.noises),
                                  mpi.gathered(share.noiseDensities)};
        if (scene.gradientTstf.automaticRange) {
            const auto [low, high] = gradientRangeForChange(scene, displayOutline, typicalOf(places.changes));
            scene.gradientTstf.rangeLow = low;
            scene.gradientTstf.rangeHigh = high;
        }
        if (fitsUnchanged) {
            // The value gradient within each process's block (its faces one-sided), gathered.
            std::vector<double> magnitudes;
            if (!block.series.steps.empty())
                addGradientMagnitudes(block.series.steps.front(), scene.stf, changeNodeStride(displayOutline),
                                      magnitudes);
            UnchangedFit fit = unchangedFitOf(places, displayOutline.size());
            fit.boundary = boundaryGradientOf(mpi.gathered(magnitudes));
            takeFit(*scene.compositorOptions.unchanged, fit);
        }
    }
    const Bounds framed = scene.camera.framing == Framing::Visible ? visible : framedOutline;
    return {std::move(scene), framed};
}

void combineRawRanges(const MpiSession& mpi, Series& block) {
    // A time-step without data in a block takes no part: +infinity as its low, -infinity as its high.
    const double infinity = std::numeric_limits<double>::infinity();
    std::vector<double> lows;
    std::vector<double> highs;
    for (const TimeStep& step : block.steps) {
        lows.push_back(std::isnan(step.rawRange[0]) ? infinity : step.rawRange[0]);
        highs.push_back(std::isnan(step.rawRange[1]) ? -infinity : step.rawRange[1]);
    }
    lows = mpi.minimum(std::move(lows));
    highs = mpi.maximum(std::move(highs));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t index = 0; index < block.steps.size(); ++index)
        block.steps[index].rawRange = lows[index] <= highs[index] ? std::array<double, 2>{lows[index], highs[index]}
                                                                  : std::array<double, 2>{nan, nan};
}

}  // namespace tstyles
