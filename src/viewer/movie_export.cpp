// Frame-by-frame movie export from the window.
#include "movie_export.h"

#include "tstyles/core/errors.h"

namespace tstyles::viewer {
namespace {

VideoSettings settingsOf(const Scene& scene) {
    return {scene.width, scene.height, scene.animation.framesPerSecond};
}

// The checks come first: the VideoWriter member is made after them.
const std::filesystem::path& checked(const std::filesystem::path& target, const Scene& scene) {
    if (scene.animation.empty())
        throwInputError("", "animation", "the scene has no animation: add keys first");
    requireWritableVideoPath(target, settingsOf(scene));
    return target;
}

}  // namespace

MovieExport::MovieExport(Scene scene, std::shared_ptr<const Series> series, DisplayFrame frame,
                         const std::filesystem::path& target)
    : scene_(std::move(scene)), series_(std::move(series)), frame_(std::move(frame)), bounds_(series_->worldBounds()),
      target_(checked(target, scene_)), writer_(target_, settingsOf(scene_)) {}

bool MovieExport::step(Renderer& renderer) {
    if (!rendering_) rendering_.emplace(renderer, *series_, bounds_, frame_);
    writer_.addFrame(rendering_->render(sceneAtFrame(scene_, next_)));
    if (++next_ < scene_.animation.frames) return false;
    writer_.finish();
    return true;
}

std::filesystem::path defaultMoviePath(const std::optional<std::filesystem::path>& sceneFile) {
    if (!sceneFile) return std::filesystem::current_path() / "movie.mp4";
    std::filesystem::path movie = *sceneFile;
    return movie.replace_extension(".mp4");
}

}  // namespace tstyles::viewer
