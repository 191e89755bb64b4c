// Scenes of one fitted series rendered and annotated as they ask (legend, title, box, ...): what
// `render`, `animate` and the viewer's movie export write. The font is opened on the first
// annotated frame, style images once each.
#pragma once

#include <optional>

#include "tstyles/annotate/font.h"
#include "tstyles/image/image.h"
#include "tstyles/render/renderer.h"
#include "tstyles/render/style_library.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles {

class AnnotatedRendering {
public:
    // `series` is the display series the renderer holds, `framed` what an automatic camera frames,
    // `frame` how the series was turned for display (fitSceneToSeries); all are kept by reference.
    AnnotatedRendering(Renderer& renderer, const Series& series, const Bounds& framed, const DisplayFrame& frame)
        : renderer_(renderer), series_(series), framed_(framed), frame_(frame) {}
    explicit AnnotatedRendering(Renderer& renderer, const SceneOnSeries& fitted)
        : AnnotatedRendering(renderer, fitted.series, fitted.framed, fitted.frame) {}
    Image render(const Scene& scene);

private:
    Renderer& renderer_;
    const Series& series_;
    const Bounds& framed_;
    const DisplayFrame& frame_;
    std::optional<Font> font_;
    StyleLibrary styles_;  // the lit spheres of styled swatches
};

}  // namespace tstyles
