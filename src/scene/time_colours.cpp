// Colours over time for the automatic scene (time_colours.h).
#include "time_colours.h"

namespace tstyles {

void applyTimeColours(Scene& scene, std::size_t stepCount) {
    const double last = double(std::max<std::size_t>(stepCount, 1) - 1);
    scene.indexTstf.curve.color = {ColorNode{0.0, {0.23, 0.40, 0.85}}, ColorNode{0.5 * last, {0.95, 0.95, 0.95}},
                                   ColorNode{last, {0.95, 0.55, 0.10}}};
    scene.gradientTstf.curve.color = {ColorNode{0.0, {0.20, 0.70, 0.25}}, ColorNode{1.0, {0.95, 0.50, 0.05}}};
}

std::string timeColoursText(std::size_t stepCount) {
    return "index TSTF blue, through white, to orange over the " + std::to_string(stepCount) +
           " time-steps; gradient TSTF green to orange over the change present";
}

}  // namespace tstyles
