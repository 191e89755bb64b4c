// One process's block of a manifest series, cut as it is read (block_reading.h).
#include "tstyles/distributed/block_reading.h"

#include "tstyles/data/manifest.h"
#include "tstyles/data/series_crop.h"
#include "tstyles/distributed/distributed_rendering.h"

namespace tstyles {

namespace {

// `step` in the display frame: the frame moves and scales a time-step's grid and leaves its values
// alone, so a time-step takes it alone as it would with the whole series.
TimeStep inDisplayFrame(TimeStep step, const std::filesystem::path& manifestPath, const DisplayFrame& frame) {
    Series alone;
    alone.manifestPath = manifestPath;
    alone.steps.push_back(std::move(step));
    alone = applyDisplayFrame(std::move(alone), frame);
    return std::move(alone.steps.front());
}

}  // namespace

BlockOfSeries readManifestBlock(const std::filesystem::path& manifest, const ReadOptions& options,
                         const Series& displayOutline, const DisplayFrame& frame, const Bounds& box) {
    ManifestLimits limits{options.maxMemoryBytes, bytesPerDensity(options.precision), {}, {}, 0};
    for (const TimeStep& step : displayOutline.steps) limits.keptVoxels += croppedVoxelCount(step, box, kBlockGhostNodes);
    // The nodes that the time-step keeps in the display frame; framing moves and scales a grid but
    // keeps its nodes, so they are the nodes to read of the file's grid.
    std::vector<std::optional<NodeBlock>> nodes(displayOutline.steps.size());
    limits.nodesToRead = [&](std::size_t index, const TimeStep& outline) {
        nodes.at(index) = nodesKeptOf(inDisplayFrame(outline, displayOutline.manifestPath, frame), box, kBlockGhostNodes);
        return nodes[index];
    };
    limits.afterStepRead = [&](std::size_t, TimeStep& step) {
        step = inDisplayFrame(std::move(step), displayOutline.manifestPath, frame);
        cropTimeStepGridToBox(step, box, kBlockGhostNodes);
    };
    Series block = loadSeries(manifest, limits);
    block.precision = options.precision;
    block.axes = displayOutline.axes;
    return {std::move(block), std::move(nodes)};
}

}  // namespace tstyles
