// Block reading or whole reading for the distributed commands (distributed_source.h).
#include "distributed_source.h"

#include <algorithm>

#include "tstyles/data/manifest.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/distributed/block_reading.h"
#include "tstyles/scene/input_kind.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::cli {
namespace {

// Why the scene file's dataset cannot be read in blocks; empty where it can.
std::string whyNotInBlocks(const Scene& scene, const std::vector<std::filesystem::path>& dataset,
                           const DatasetOptions& options) {
    if (dataset.size() != 1 || !isManifestInput(dataset.front()))
        return "only a tstyles manifest is read in blocks (`tstyles convert` makes one)";
    const bool readingOptions = !options.variable.empty() || !options.timeDimension.empty() || options.indexAxes ||
                                options.steps || options.range || options.resample || options.rawDims || options.fit ||
                                !options.solutions.empty() || options.block != 0;
    if (readingOptions) return "a reader's options were given";
    if (scene.gradientTstf.automaticRange)
        return "the scene's gradient TSTF range is \"auto\", which is fitted to the values (a fixed range reads blocks)";
    if (scene.camera.framing == Framing::Visible)
        return "the camera frames the visible data, which the values decide (\"frame\": \"series\" reads blocks)";
    return "";
}

}  // namespace

DistributedSource openDistributedSource(const std::vector<std::filesystem::path>& inputs,
                                        const std::vector<std::filesystem::path>& datasetFiles,
                                        const DatasetOptions& datasetOptions) {
    if (inputs.size() != 1 || classifyInput(inputs.front()) != InputKind::Scene)
        return {openSceneOrDataset(inputs, datasetFiles, datasetOptions), std::nullopt,
                "the automatic scene is fitted to the values (`tstyles scene` writes it to a file to fix)"};
    Scene scene = loadScene(inputs.front());
    const std::vector<std::filesystem::path> dataset =
        datasetFiles.empty() ? std::vector<std::filesystem::path>{scene.dataset} : datasetFiles;
    std::string reason = whyNotInBlocks(scene, dataset, datasetOptions);
    if (!reason.empty()) return {openSceneOrDataset(inputs, datasetFiles, datasetOptions), std::nullopt, reason};
    Series outline = loadSeriesOutline(dataset.front());
    outline.precision = toReadOptions(datasetOptions).precision;
    return {SceneAndSeries{std::move(scene), std::move(outline), {}}, dataset.front(), ""};
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
        [&](const Bounds& box) { return readManifestBlock(manifest, options, displayOutline, frame, box); }, upload);
}

std::string readingText(const DistributedSource& source, const Series& series) {
    std::string text = source.blockManifest ? "each process read only its block"
                                            : "every process read the whole series: " + source.wholeReason;
    const auto whole = std::count_if(series.steps.begin(), series.steps.end(), [](const TimeStep& step) {
        return !std::holds_alternative<RectilinearGrid>(step.grid);
    });
    if (whole > 0)
        text += "; " + std::to_string(whole) + " of its " + std::to_string(series.size()) +
                " time-steps are beam or structured grids, which every process keeps whole (their samples "
                "still split)";
    return text;
}

}  // namespace tstyles::cli
