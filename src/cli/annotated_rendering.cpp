// Rendering plus annotations, for the headless commands.
#include "annotated_rendering.h"

#include "tstyles/annotate/scene_annotations.h"

namespace tstyles::cli {

Image AnnotatedRendering::render(const Scene& scene) {
    const Bounds all = fitted_.series.worldBounds();
    Image image = renderImage(renderer_, scene, fitted_.framed, all);
    if (!scene.annotations.any()) return image;
    if (!font_) font_ = Font::openDefault();
    const View view = resolveView(scene.camera, fitted_.framed, all, scene.width, scene.height);
    drawAnnotations(image, scene, fitted_.series, fitted_.frame, view, *font_,
                    [this](const std::string& style) { return &styles_.image(style); });
    return image;
}

void addAnnotationOptions(CLI::App& command, AnnotationOptions& options) {
    command.add_flag("--legend", options.legend,
                     "Draw the legend: time-step colours with their times, or the colour bar of change, and the STF");
    command.add_flag("--annotate", options.annotate,
                     "Draw the legend, a caption (compositor, time range), the box with ticks and a scale bar");
    command.add_option("--title", options.title, "A title in the top-left corner");
}

void applyAnnotationOptions(Scene& scene, const AnnotationOptions& options) {
    Annotations& annotations = scene.annotations;
    annotations.legend = annotations.legend || options.legend || options.annotate;
    if (options.annotate) annotations.caption = annotations.box = annotations.scaleBar = true;
    if (options.title) annotations.title = *options.title;
}

}  // namespace tstyles::cli
