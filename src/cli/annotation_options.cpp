// The annotation options of render and animate.
#include "annotation_options.h"

#include <CLI/CLI.hpp>

namespace tstyles::cli {

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
