// The legends of the transfer functions a scene shows (time-step swatches or strip, the gradient
// TSTF's colour bar, the STF's colour bar), as panels to be placed. Private to src/annotate.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "annotation_panels.h"

namespace tstyles {

struct LegendInputs {
    const Scene& scene;
    const Series& series;
    glm::ivec2 steps;                        // the exposed time-steps, first and last
    const std::vector<std::string>& labels;  // of every time-step (timeStepLabels)
    StyleImages styles;
    PanelMetrics metrics;
    glm::ivec2 imageSize;
    double maxWidth;  // a panel's widest; longer labels and headings are shortened
};

// In the order they stack from the legend's corner. The drafts refer to the scene and the font.
std::vector<PanelDraft> legendDrafts(const LegendInputs& in);

}  // namespace tstyles
