// Scenes of one fitted series rendered and annotated as they ask (legend, title, box, ...): what
// `render`, `animate` and the viewer's movie export write. The font is opened on the first
// annotated frame, style images once each.
#pragma once

#include <optional>

#include "tstyles/annotate/font.h"
#include "tstyles/annotate/scene_annotations.h"
#include "tstyles/image/image.h"
#include "tstyles/render/renderer.h"
#include "tstyles/render/style_library.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles {

// Draws a scene's annotations onto frames of one display series. Reads only the series' times,
// grids and metadata, never its values.
class SceneAnnotator {
public:
    // `series` is the display series, `framed` what an automatic camera frames, `frame` how the
    // series was turned for display (fitSceneToSeries); all are kept by reference.
    SceneAnnotator(const Series& series, const Bounds& framed, const DisplayFrame& frame)
        : series_(series), framed_(framed), frame_(frame) {}
    void annotate(Image& image, const Scene& scene);
    // What the scene's frames are rendered with: the view of its camera on the series, moved and
    // shrunk on the image beside the panels where it has annotations (pictureView), so that they
    // never cover the data.
    View viewOf(const Scene& scene);

private:
    StyleImages styleImages();

    const Series& series_;
    const Bounds& framed_;
    const DisplayFrame& frame_;
    std::optional<Font> font_;
    StyleLibrary styles_;  // the lit spheres of styled swatches
};

class AnnotatedRendering {
public:
    // The renderer holds `series` (see SceneAnnotator for the others).
    AnnotatedRendering(Renderer& renderer, const Series& series, const Bounds& framed, const DisplayFrame& frame)
        : renderer_(renderer), annotator_(series, framed, frame) {}
    explicit AnnotatedRendering(Renderer& renderer, const SceneOnSeries& fitted)
        : AnnotatedRendering(renderer, fitted.series, fitted.framed, fitted.frame) {}
    // `options` other than the size (which the scene gives): the renderer's choices, e.g. the
    // gradient method.
    Image render(const Scene& scene, FrameOptions options = {});

private:
    Renderer& renderer_;
    SceneAnnotator annotator_;
};

}  // namespace tstyles
