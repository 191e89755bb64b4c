// The scene's annotations (legend, title, caption, box, scale bar) over the volume area: drawn by
// the same code as headless images (drawAnnotations) into a transparent image of the frame's size,
// kept as a texture, and put on top of the rendered image by ImGui. Redrawn only when the scene,
// the camera or the size changes.
#pragma once

#include <optional>

#include "tstyles/annotate/font.h"
#include "tstyles/data/display_frame.h"
#include "tstyles/data/series.h"
#include "tstyles/gl/objects.h"
#include "tstyles/render/style_library.h"
#include "tstyles/scene/scene.h"
#include "ui_geometry.h"

namespace tstyles::viewer {

class AnnotationOverlay {
public:
    // Needs a current OpenGL context (the texture). `rect` is the volume area in window
    // coordinates, `frameSize` its size in framebuffer pixels.
    void draw(const ScreenRect& rect, glm::ivec2 frameSize, const Scene& scene, const Series& series,
              const DisplayFrame& frame);

private:
    void redraw(glm::ivec2 frameSize, const Scene& scene, const Series& series, const DisplayFrame& frame);

    std::optional<Font> font_;
    StyleLibrary styles_;
    std::optional<Texture> texture_;
    glm::ivec2 textureSize_{0};
    std::optional<Scene> drawnScene_;  // what the texture shows
};

}  // namespace tstyles::viewer
