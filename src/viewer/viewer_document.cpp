// Opening scenes and datasets for the viewer.
#include "viewer_document.h"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/data/manifest.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::viewer {
namespace {

bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code error;
    const bool same = std::filesystem::equivalent(a, b, error);
    return !error && same;
}

std::shared_ptr<const Series> seriesFor(const std::filesystem::path& manifest, const ViewerDocument* current) {
    if (current != nullptr && current->series && sameFile(manifest, current->series->manifestPath))
        return current->series;
    return std::make_shared<const Series>(loadSeries(manifest));
}

}  // namespace

ViewerInputKind classifyViewerInput(const std::filesystem::path& path) {
    if (std::filesystem::is_directory(path)) return ViewerInputKind::Dataset;
    std::ifstream stream(path);
    if (!stream) return ViewerInputKind::Scene;  // let the scene reader say what is wrong
    std::stringstream text;
    text << stream.rdbuf();
    const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false, true);
    if (json.is_object() && !json.contains("dataset") && (json.contains("time_steps") || json.contains("format")))
        return ViewerInputKind::Dataset;
    return ViewerInputKind::Scene;
}

ViewerDocument openDocument(const std::filesystem::path& path, const ViewerDocument* current) {
    if (!std::filesystem::exists(path)) throwInputError(path, "", "no such file or folder");
    ViewerDocument document;
    if (classifyViewerInput(path) == ViewerInputKind::Dataset) {
        document.series = seriesFor(path, current);
        document.scene.dataset = document.series->manifestPath;
    } else {
        document.scene = loadScene(path);
        document.series = seriesFor(document.scene.dataset, current);
        document.sceneFile = std::filesystem::absolute(path).lexically_normal();
    }
    if (document.series->size() == 0) throwInputError(document.series->manifestPath, "", "the series has no time-steps");
    document.histogram = (current != nullptr && current->series == document.series)
                             ? current->histogram
                             : std::make_shared<const DensityHistogram>(computeDensityHistogram(*document.series));
    document.openedCamera = document.scene.camera;
    return document;
}

std::filesystem::path defaultViewerInput(const std::filesystem::path& dataDirectory) {
    const std::filesystem::path scene = dataDirectory / "scenes" / "figure1-styled-focus-step3.json";
    if (std::filesystem::exists(scene)) return scene;
    const std::filesystem::path dataset = dataDirectory / "superellipsoid" / "series.json";
    if (std::filesystem::exists(dataset)) return dataset;
    throwInputError(dataDirectory, "",
                    "no bundled scene (scenes/figure1-styled-focus-step3.json) or dataset (superellipsoid/series.json) "
                    "here; build the project to generate it, set TSTYLES_DATA_DIR, or pass a scene or dataset");
}

}  // namespace tstyles::viewer
