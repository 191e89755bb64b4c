// Rendering plus annotations, for the headless commands and the viewer's movie export.
#include "tstyles/render/annotated_rendering.h"

#include "tstyles/annotate/scene_annotations.h"

namespace tstyles {

View SceneAnnotator::viewOf(const Scene& scene) const {
    return resolveView(scene.camera, framed_, series_.worldBounds(), scene.width, scene.height);
}

void SceneAnnotator::annotate(Image& image, const Scene& scene) {
    if (!scene.annotations.any()) return;
    if (!font_) font_ = Font::openDefault();
    drawAnnotations(image, scene, series_, frame_, viewOf(scene), *font_,
                    [this](const std::string& style) { return &styles_.image(style); });
}

Image AnnotatedRendering::render(const Scene& scene, FrameOptions options) {
    const View view = annotator_.viewOf(scene);
    options.size = {scene.width, scene.height};
    renderer_.draw(scene, view, options);
    Image image = renderer_.readFrame();
    annotator_.annotate(image, scene);
    return image;
}

}  // namespace tstyles
