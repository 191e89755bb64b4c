// Block reading or whole reading for the distributed commands (distributed_source.h).
#include "distributed_source.h"

#include <algorithm>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/data/manifest.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/distributed/block_reading.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/input_kind.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::cli {
namespace {

// Why the dataset cannot be read in blocks; empty where it can.
std::string whyNotInBlocks(const std::vector<std::filesystem::path>& dataset, const DatasetOptions& options) {
    if (dataset.size() != 1 || !isManifestInput(dataset.front()))
        return "only a tstyles manifest is read in blocks (`tstyles convert` makes one)";
    // Only what a manifest takes too (the precision, the memory limit) keeps the blocks.
    for (const auto& [key, texts] : options.texts)
        if (const ReaderOptionLine* line = readerOptionNamed(key); line && !line->forManifest)
            return "a reader's options were given";
    return "";
}

Series outlineFor(const std::filesystem::path& manifest, const DatasetOptions& datasetOptions) {
    Series outline = loadSeriesOutline(manifest);
    outline.precision = toReadOptions(datasetOptions).precision;
    return outline;
}

}  // namespace

DistributedSource openDistributedSource(const std::vector<std::filesystem::path>& inputs,
                                        const std::vector<std::filesystem::path>& datasetFiles,
                                        const DatasetOptions& datasetOptions) {
    const auto wholeSeries = [&](std::string reason) {
        return DistributedSource{openSceneOrDataset(inputs, datasetFiles, datasetOptions, RenderedBy::MergedBlocks),
                                 std::nullopt, std::move(reason)};
    };
    if (inputs.size() != 1 || classifyInput(inputs.front()) != InputKind::Scene) {
        if (!datasetFiles.empty()) return wholeSeries("");  // refused there: --dataset needs a scene file
        if (std::string reason = whyNotInBlocks(inputs, datasetOptions); !reason.empty())
            return wholeSeries(std::move(reason));
        for (const auto& input : inputs)
            if (userPathKind({}, input) == PathKind::Missing) throwInputError(input, "", "no such file or folder");
        Series outline = outlineFor(inputs.front(), datasetOptions);
        // The opacity window comes from the blocks' histogram (fitting_over_blocks.h).
        AutomaticScene automatic =
            automaticScene(outline, userAbsolutePath({}, inputs.front()), OpacityWindow{}, RenderedBy::MergedBlocks);
        return {SceneAndSeries{std::move(automatic.scene), std::move(outline), std::move(automatic.explanation)},
                inputs.front(), "", true};
    }
    Scene scene = loadScene(inputs.front());
    const std::vector<std::filesystem::path> dataset =
        datasetFiles.empty() ? std::vector<std::filesystem::path>{scene.dataset} : datasetFiles;
    if (std::string reason = whyNotInBlocks(dataset, datasetOptions); !reason.empty())
        return wholeSeries(std::move(reason));
    Series outline = outlineFor(dataset.front(), datasetOptions);
    return {SceneAndSeries{std::move(scene), std::move(outline), {}}, dataset.front(), "", false};
}

DistributedRendering startDistributedRendering(const MpiSession& mpi, Renderer& renderer, SceneOnSeries fitted,
                                               const DistributedSource& source, const DatasetOptions& datasetOptions,
                                               const DistributedRendering::BlockUpload& upload) {
    if (!source.blockManifest) return DistributedRendering(mpi, renderer, std::move(fitted), upload);
    const ReadOptions options = toReadOptions(datasetOptions);
    const Series displayOutline = fitted.series;  // an outline: grids without values
    const DisplayFrame frame = fitted.frame;
    const std::filesystem::path manifest = *source.blockManifest;
    return DistributedRendering(
        mpi, renderer, std::move(fitted),
        [&](const Bounds& box) { return readManifestBlock(manifest, options, displayOutline, frame, box); }, upload,
        source.automaticOpacity);
}

std::string readingText(const DistributedSource& source, const Series& series) {
    std::string text = source.blockManifest ? "each process read only its block"
                                            : "every process read the whole series: " + source.wholeReason;
    const auto whole = std::count_if(series.steps.begin(), series.steps.end(), [](const TimeStep& step) {
        return std::holds_alternative<StructuredGrid>(step.grid);
    });
    if (whole > 0)
        text += "; " + std::to_string(whole) + " of its " + std::to_string(series.size()) +
                " time-steps are structured grids, which every process keeps whole (their samples still split)";
    return text;
}

}  // namespace tstyles::cli
