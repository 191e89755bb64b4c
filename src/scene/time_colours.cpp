// Colours over time for the automatic scene (time_colours.h).
#include "time_colours.h"

#include "tstyles/scene/color_map.h"

namespace tstyles {

void applyTimeColours(Scene& scene, std::size_t stepCount) {
    const double last = double(std::max<std::size_t>(stepCount, 1) - 1);
    scene.indexTstf.curve.color = colorNodesFromMap(*colorMapNamed("temporal"), 0.0, last, true);
    scene.gradientTstf.curve.color = colorNodesFromMap(*colorMapNamed("green-orange"), 0.0, 1.0, false);
}

std::string timeColoursText(std::size_t stepCount) {
    return "index TSTF from the colour map \"temporal\" (blue, through white, to orange) over the " +
           std::to_string(stepCount) + " time-steps; gradient TSTF from \"green-orange\" over the change present";
}

}  // namespace tstyles
