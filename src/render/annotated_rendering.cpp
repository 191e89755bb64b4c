// Rendering plus annotations, for the headless commands and the viewer's movie export.
#include "tstyles/render/annotated_rendering.h"

#include "tstyles/annotate/scene_annotations.h"

namespace tstyles {

Image AnnotatedRendering::render(const Scene& scene) {
    const Bounds all = series_.worldBounds();
    Image image = renderImage(renderer_, scene, framed_, all);
    if (!scene.annotations.any()) return image;
    if (!font_) font_ = Font::openDefault();
    const View view = resolveView(scene.camera, framed_, all, scene.width, scene.height);
    drawAnnotations(image, scene, series_, frame_, view, *font_,
                    [this](const std::string& style) { return &styles_.image(style); });
    return image;
}

}  // namespace tstyles
