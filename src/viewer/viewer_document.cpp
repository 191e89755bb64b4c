// Opening scenes and datasets for the viewer.
#include "viewer_document.h"

#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::viewer {
namespace {

bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code error;
    const bool same = std::filesystem::equivalent(a, b, error);
    return !error && same;
}

std::shared_ptr<const Series> seriesFor(const std::vector<std::filesystem::path>& paths,
                                        const ViewerDocument* current, const ReadOptions& readOptions) {
    if (paths.size() == 1 && current != nullptr && current->series &&
        sameFile(paths.front(), current->series->manifestPath))
        return current->series;
    return std::make_shared<const Series>(openSeries(paths, readOptions));
}

}  // namespace

ViewerInputKind classifyViewerInput(const std::filesystem::path& path) {
    if (std::filesystem::is_directory(path)) return ViewerInputKind::Dataset;
    std::ifstream stream(path, std::ios::binary);
    if (!stream) return ViewerInputKind::Scene;  // let the scene reader say what is wrong
    char first = 0;
    while (stream.get(first) && std::isspace(static_cast<unsigned char>(first))) {
    }
    // Not JSON (which starts with an object or a comment): a data file, left to the opener.
    if (!isManifestInput(path) && (!stream || (first != '{' && first != '/'))) return ViewerInputKind::Dataset;
    stream.clear();
    stream.seekg(0);
    std::stringstream text;
    text << stream.rdbuf();
    const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false, true);
    if (json.is_object() && !json.contains("dataset") && (json.contains("time_steps") || json.contains("format")))
        return ViewerInputKind::Dataset;
    return ViewerInputKind::Scene;
}

ViewerDocument openDocument(const std::vector<std::filesystem::path>& paths, const ViewerDocument* current,
                            const ReadOptions& readOptions) {
    if (paths.empty()) throw std::invalid_argument("openDocument: no path");
    for (const auto& path : paths)
        if (!std::filesystem::exists(path)) throwInputError(path, "", "no such file or folder");
    ViewerDocument document;
    if (paths.size() > 1 || classifyViewerInput(paths.front()) == ViewerInputKind::Dataset) {
        document.series = seriesFor(paths, current, readOptions);
        document.scene.dataset = document.series->manifestPath;
    } else {
        document.scene = loadScene(paths.front());
        document.series = seriesFor({document.scene.dataset}, current, readOptions);
        document.sceneFile = std::filesystem::absolute(paths.front()).lexically_normal();
    }
    if (document.series->size() == 0) throwInputError(document.series->manifestPath, "", "the series has no time-steps");
    document.histogram = (current != nullptr && current->series == document.series)
                             ? current->histogram
                             : std::make_shared<const DensityHistogram>(computeDensityHistogram(*document.series));
    document.openedCamera = document.scene.camera;
    return document;
}

ViewerDocument openDocument(const std::filesystem::path& path, const ViewerDocument* current) {
    return openDocument(std::vector<std::filesystem::path>{path}, current, ReadOptions{});
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
