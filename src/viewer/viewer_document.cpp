// Opening scenes and datasets for the viewer.
#include "viewer_document.h"

#include <stdexcept>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/data/isolated_reading.h"
#include "camera_controller.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/input_kind.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::viewer {
namespace {

bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code error;
    const bool same = std::filesystem::equivalent(a, b, error);
    return !error && same;
}

// The series in the scene's display frame, with the scene's automatic parts fitted to it; the
// current document's series when it is the same file shown the same way.
std::shared_ptr<const Series> fitSeries(Scene& scene, const std::vector<std::filesystem::path>& paths,
                                        const ViewerDocument* current, Series* opened, const ReadOptions& readOptions,
                                        DisplayFrame& frame) {
    if (opened == nullptr && paths.size() == 1 && current != nullptr && current->series &&
        sameFile(paths.front(), current->series->manifestPath) && current->scene.display == scene.display) {
        if (scene.gradientTstf.automaticRange) {
            // The fit depends on the compositor (a trend's range is signed): refit only when it changed.
            const auto [low, high] = scene.compositor == current->scene.compositor
                                         ? std::pair{current->scene.gradientTstf.rangeLow,
                                                     current->scene.gradientTstf.rangeHigh}
                                         : automaticGradientRange(scene, *current->series);
            scene.gradientTstf.rangeLow = low;
            scene.gradientTstf.rangeHigh = high;
        }
        if (auto& unchanged = scene.compositorOptions.unchanged; unchanged && unchanged->automatic) {
            // Fitted to the STF's visible places: refit only when the STF changed.
            const auto& kept = current->scene.compositorOptions.unchanged;
            takeFit(*unchanged, kept && kept->automatic && current->scene.stf == scene.stf
                                    ? fittedOf(*kept)
                                    : automaticUnchangedFit(scene, *current->series));
        }
        frame = current->frame;
        return current->series;
    }
    SceneOnSeries fitted =
        fitSceneToSeries(scene, opened ? std::move(*opened) : openSeriesIsolated(paths, readOptions));
    // The viewer's camera code frames the whole series; what frames the visible part is made explicit.
    if (fitted.scene.camera.framing == Framing::Visible)
        fitted.scene.camera = frameExplicitly(fitted.scene.camera, fitted.framed, {scene.width, scene.height});
    scene = std::move(fitted.scene);
    frame = std::move(fitted.frame);
    return std::make_shared<const Series>(std::move(fitted.series));
}

}  // namespace

ViewerDocument openDocument(const std::vector<std::filesystem::path>& paths, const ViewerDocument* current,
                            const ReadOptions& readOptions) {
    if (paths.empty()) throw std::invalid_argument("openDocument: no path");
    for (const auto& path : paths)
        if (userPathKind(PathSource{}, path) == PathKind::Missing) throwInputError(path, "", "no such file or folder");
    ViewerDocument document;
    if (paths.size() > 1 || classifyInput(paths.front()) == InputKind::Dataset) {
        Series raw = openSeriesIsolated(paths, readOptions);
        document.scene = automaticScene(raw, raw.manifestPath).scene;
        document.series = fitSeries(document.scene, paths, current, &raw, readOptions, document.frame);
    } else {
        document.scene = loadScene(paths.front());
        document.series =
            fitSeries(document.scene, {document.scene.dataset}, current, nullptr, readOptions, document.frame);
        document.sceneFile = userAbsolutePath(PathSource{}, paths.front());
    }
    if (document.series->size() == 0) throwInputError(document.series->manifestPath, "", "the series has no time-steps");
    if (document.sceneFile) {
        // As `render` does: settings that name time-steps the series lacks fail on opening, named.
        checkTimeStepsFit(document.scene, document.series->size(), *document.sceneFile);
    }
    document.histogram = (current != nullptr && current->series == document.series)
                             ? current->histogram
                             : std::make_shared<const DensityHistogram>(computeDensityHistogram(*document.series));
    document.openedCamera = document.scene.camera;
    std::vector<double> times;
    for (const TimeStep& step : document.series->steps) times.push_back(step.time);
    document.timeLabels = formatTimes(times, document.series->time);
    return document;
}

ViewerDocument openDocument(const std::filesystem::path& path, const ViewerDocument* current) {
    return openDocument(std::vector<std::filesystem::path>{path}, current, ReadOptions{});
}

std::filesystem::path defaultViewerInput(const std::filesystem::path& dataDirectory) {
    const std::filesystem::path scene = dataDirectory / "scenes" / "figure1-styled-focus-step3.json";
    // The data folder comes from TSTYLES_DATA_DIR or the build: a name the system refuses is just absent.
    std::error_code error;
    if (std::filesystem::exists(scene, error)) return scene;
    const std::filesystem::path dataset = dataDirectory / "superellipsoid" / "series.json";
    if (std::filesystem::exists(dataset, error)) return dataset;
    throwInputError(dataDirectory, "",
                    "no bundled scene (scenes/figure1-styled-focus-step3.json) or dataset (superellipsoid/series.json) "
                    "here; build the project to generate it, set TSTYLES_DATA_DIR, or pass a scene or dataset");
}

}  // namespace tstyles::viewer
