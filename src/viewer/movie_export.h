// The viewer's movie export: the scene's animation rendered one frame per UI frame through the
// same code as `tstyles animate`, so the window stays responsive and the export can be cancelled
// (the half-written movie is then removed).
#pragma once

#include <filesystem>
#include <memory>

#include "tstyles/render/annotated_rendering.h"
#include "tstyles/video/video_file.h"

namespace tstyles::viewer {

class MovieExport {
public:
    // The open document's scene (with its animation), its display series and display frame; the
    // series is shared, not copied. InputError naming `target` when the movie cannot be written.
    MovieExport(Scene scene, std::shared_ptr<const Series> series, DisplayFrame frame,
                const std::filesystem::path& target);
    // Renders and encodes the next frame with `renderer` (which holds the series); true once the
    // last frame is in and the movie is in place.
    bool step(Renderer& renderer);
    double progress() const { return double(next_) / double(scene_.animation.frames); }
    const std::filesystem::path& target() const { return target_; }

private:
    Scene scene_;
    std::shared_ptr<const Series> series_;
    DisplayFrame frame_;
    Bounds bounds_;
    std::filesystem::path target_;
    VideoWriter writer_;
    int next_ = 0;
    std::optional<AnnotatedRendering> rendering_;
};

// Where a movie of the scene goes by default: beside its scene file, else in the current folder.
std::filesystem::path defaultMoviePath(const std::optional<std::filesystem::path>& sceneFile);

}  // namespace tstyles::viewer
