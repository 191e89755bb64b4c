// One process's block of a manifest series, cut as it is read (block_reading.h).
#include "tstyles/distributed/block_reading.h"

#include "tstyles/data/manifest.h"
#include "tstyles/data/series_crop.h"
#include "tstyles/distributed/distributed_rendering.h"

namespace tstyles {

Series readManifestBlock(const std::filesystem::path& manifest, const ReadOptions& options,
                         const Series& displayOutline, const DisplayFrame& frame, const Bounds& box) {
    ManifestLimits limits{options.maxMemoryBytes, bytesPerDensity(options.precision), {}, 0};
    for (const TimeStep& step : displayOutline.steps) limits.keptVoxels += croppedVoxelCount(step, box, kBlockGhostNodes);
    limits.afterStepRead = [&](std::size_t, TimeStep& step) {
        // The display frame moves and scales a time-step's grid and leaves its values alone, so a
        // time-step takes it alone as it would with the whole series.
        Series alone;
        alone.manifestPath = displayOutline.manifestPath;
        alone.steps.push_back(std::move(step));
        alone = applyDisplayFrame(std::move(alone), frame);
        step = std::move(alone.steps.front());
        cropTimeStepToBox(step, box, kBlockGhostNodes);
    };
    Series block = loadSeries(manifest, limits);
    block.precision = options.precision;
    block.axes = displayOutline.axes;
    return block;
}

}  // namespace tstyles
