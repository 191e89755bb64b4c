// Colours over time for the automatic scene (time_colours.h).
#include "tstyles/scene/time_colours.h"

#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/color_map.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

// Where the gradient TSTF leaves unchanging voxels faint, so that change stands out.
constexpr double kUnchangedOpacity = 0.15;

}  // namespace

void applyTimeColours(Scene& scene, std::size_t stepCount) {
    const double last = double(std::max<std::size_t>(stepCount, 1) - 1);
    scene.indexTstf.curve.color = colorNodesFromMap(*colorMapNamed("temporal"), 0.0, last, true);
    applyAutomaticGradientColours(scene);
}

std::string applyAutomaticGradientColours(Scene& scene) {
    const AutomaticRange range = compositorInfo(scene.compositor).range;
    const bool signedValues = range == AutomaticRange::SignedChange || range == AutomaticRange::SignedPerTime;
    if (signedValues) {
        // Falls blue, rises red; no change, in the middle of the range, as faint as no change is
        // for the unsigned compositors.
        scene.gradientTstf.curve.color = colorNodesFromMap(*colorMapNamed("blue-red"), 0.0, 1.0, false);
        scene.gradientTstf.curve.opacity = {OpacityNode{0.0, 1.0}, OpacityNode{0.5, kUnchangedOpacity},
                                            OpacityNode{1.0, 1.0}};
        return "gradient TSTF from the diverging \"blue-red\": falls blue, rises red, no change faint";
    }
    scene.gradientTstf.curve.color = colorNodesFromMap(*colorMapNamed("green-orange"), 0.0, 1.0, false);
    scene.gradientTstf.curve.opacity = {OpacityNode{0.0, kUnchangedOpacity}, OpacityNode{1.0, 1.0}};
    return "gradient TSTF from \"green-orange\", no change faint";
}

std::string timeColoursText(std::size_t stepCount) {
    return "index TSTF from the colour map \"temporal\" (blue, through white, to orange) over the " +
           std::to_string(stepCount) + " time-steps; gradient TSTF from \"green-orange\" over the change present";
}

}  // namespace tstyles
