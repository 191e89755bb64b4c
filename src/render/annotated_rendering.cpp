// Rendering plus annotations, for the headless commands and the viewer's movie export.
#include "tstyles/render/annotated_rendering.h"

#include "tstyles/annotate/scene_annotations.h"

namespace tstyles {

View SceneAnnotator::viewOf(const Scene& scene) {
    const View camera = resolveView(scene.camera, framed_, series_.worldBounds(), scene.width, scene.height);
    if (!scene.annotations.any()) return camera;
    if (!font_) font_ = Font::openDefault();
    return pictureView({scene.width, scene.height}, scene, series_, frame_, camera, *font_, styleImages(), framed_);
}

void SceneAnnotator::annotate(Image& image, const Scene& scene) {
    if (!scene.annotations.any()) return;
    if (!font_) font_ = Font::openDefault();
    const View camera = resolveView(scene.camera, framed_, series_.worldBounds(), scene.width, scene.height);
    drawAnnotations(image, scene, series_, frame_, camera, *font_, styleImages(), framed_);
}

StyleImages SceneAnnotator::styleImages() {
    return [this](const std::string& style) { return &styles_.image(style); };
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
