// Changing the ray mode where the user chooses it (the window's list): the new mode comes with the
// STF, ray step and unchanged-places opacity the automatic scene gives it (applyAutomaticRay) where
// the scene still holds the automatic ones of its current mode, so that a maximum projection chosen
// over a composited automatic scene is the one `render --ray maximum` makes, and what the user set
// stays. GL-free.
#pragma once

#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

// What switchRayMode carried over from the automatic scene of the new mode.
struct RayModeSwitch {
    bool stf = false;
    bool step = false;
    bool unchangedOpacity = false;
};

// `shown`: the series already turned into the scene's display frame, as the window holds it.
RayModeSwitch switchRayMode(Scene& scene, const Series& shown, RayMode mode);

}  // namespace tstyles
