// Scenes of one fitted series rendered headless and annotated as they ask (legend, title, box...):
// what `render` and `animate` write. The font is opened once, on the first annotated frame.
#pragma once

#include <optional>

#include <CLI/CLI.hpp>

#include "tstyles/annotate/font.h"
#include "tstyles/image/image.h"
#include "tstyles/render/renderer.h"
#include "tstyles/render/style_library.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::cli {

class AnnotatedRendering {
public:
    AnnotatedRendering(Renderer& renderer, const SceneOnSeries& fitted) : renderer_(renderer), fitted_(fitted) {}
    Image render(const Scene& scene);

private:
    Renderer& renderer_;
    const SceneOnSeries& fitted_;
    std::optional<Font> font_;
    StyleLibrary styles_;  // the lit spheres of styled swatches
};

// --legend and --annotate: switch the scene's annotations on from the command line.
struct AnnotationOptions {
    bool legend = false;
    bool annotate = false;
    std::optional<std::string> title;
};
void addAnnotationOptions(CLI::App& command, AnnotationOptions& options);
void applyAnnotationOptions(Scene& scene, const AnnotationOptions& options);

}  // namespace tstyles::cli
