// A scene's annotations drawn onto its rendered image (docs/annotations.md): the legend of the
// transfer functions in use (time-step swatches with the data's times, a colour bar of change in
// the data's units, the STF's colour and opacity over the data values), a title, a caption, the
// series' box with labelled ticks and a scale bar. The CLI, `animate` and the viewer all draw
// through here, so a saved scene renders the same annotated picture everywhere.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/annotate/canvas.h"
#include "tstyles/data/display_frame.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/camera.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

// What a placed element of the annotations is (docs/annotations.md, "Layout").
enum class AnnotationKind { Title, Caption, Legend, ScaleBar, ScaleBarLabel, AxisTitle, TickLabel };
std::string toString(AnnotationKind kind);  // "title", "caption", "legend", "scale bar", ...

// One element the layout placed: its rectangle (whole pixels) holds all it draws, and no two
// elements' rectangles overlap or leave the image. The box's edges and tick marks are not elements:
// they are part of the picture, under the elements, like the volume.
struct PlacedAnnotation {
    AnnotationKind kind = AnnotationKind::Title;
    Rect rect;
    std::string text;  // the text shown (shortened with "\u2026" where it did not fit); a legend's heading
};

// What the annotations drew where, for tests and for the viewer's hit-testing.
struct AnnotationLayout {
    std::vector<PlacedAnnotation> elements;  // everything placed, in the order it was placed
    std::vector<Rect> panels;                // every legend, title and caption panel
    std::vector<Rect> stepSwatches;          // the index TSTF legend's swatch of each exposed time-step
    std::vector<int> swatchSteps;            // the time-step of each swatch
    std::vector<std::string> swatchLabels;
};

// A style's lit-sphere image by reference (the renderer's StyleLibrary), so that a styled time-step's
// swatch shows its lit sphere; null or an empty function: flat swatches of the tint.
using StyleImages = std::function<const Image*(const std::string& style)>;

// The annotations laid out for an image of `imageSize`, not drawn yet: the layout, and how to draw
// what lies under the elements (the box's edges and tick marks) and each element alone. The
// drawings refer to the arguments, which must outlive the plan.
struct AnnotationPlan {
    AnnotationLayout layout;
    // The view the picture is drawn with: the one planned for, or where the plan keeps a bounds
    // clear (planAnnotations' `keepClear`), that view moved and shrunk on the image.
    View view;
    std::function<void(Canvas&)> drawUnderlay;
    std::vector<std::function<void(Canvas&)>> drawElements;  // one per layout.elements entry
};

// `series` is the display series (fitSceneToSeries), `frame` the display frame it was turned by:
// ticks and the scale bar are given in the file's units. With `keepClear` (the bounds of the data
// the picture shows: SceneOnSeries::framed), the panels never cover the data: where the bounds'
// footprint on the image meets the title, caption, legends or the scale bar's corner, the plan's
// view moves and shrinks the picture into the room they leave (docs/annotations.md, "Layout");
// where that room would hold the picture at less than half its size, legends give way from the
// last. Without it, the plan's view is `view` and the panels may lie over the picture (the window).
AnnotationPlan planAnnotations(glm::ivec2 imageSize, const Scene& scene, const Series& series,
                               const DisplayFrame& frame, const View& view, const Font& font,
                               const StyleImages& styles = {}, const std::optional<Bounds>& keepClear = {});

// The plan drawn: the underlay, then every element. The image must have been rendered with the
// plan's view (pictureView below, for the same arguments).
AnnotationLayout drawAnnotations(Image& image, const Scene& scene, const Series& series, const DisplayFrame& frame,
                                 const View& view, const Font& font, const StyleImages& styles = {},
                                 const std::optional<Bounds>& keepClear = {});

// The view a picture annotated by drawAnnotations with these arguments is rendered with: `view`
// itself where the scene has no annotations.
View pictureView(glm::ivec2 imageSize, const Scene& scene, const Series& series, const DisplayFrame& frame,
                 const View& view, const Font& font, const StyleImages& styles, const Bounds& keepClear);

// The text size for an image: the scene's font size scaled from a 512-pixel-high image.
int annotationPixelSize(const Scene& scene, int imageHeight);

// Labels of the series' time-steps: dates or times with units where the file gives them, else
// "time-step i", with its stamp in brackets where the stamps are not the indices ("time-step 3 (0.533)").
std::vector<std::string> timeStepLabels(const Series& series);

// 1, 2 or 5 times a power of ten: tick spacing for about `count` ticks over `span`.
double niceStep(double span, int count);
// "12.5", "0.003", "1.2e+06": short labels for ticks.
std::string tickLabel(double value, double step);

}  // namespace tstyles
