// The automatic parts of the current mode are recognised by making them again: equal means the
// user has not changed them.
#include "tstyles/scene/ray_mode_switch.h"

#include <cmath>

#include "tstyles/scene/automatic_opacity.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles {
namespace {

// Steps made through the display frame (the automatic scene, from the series as read) and on the
// series already in it (here) agree up to rounding.
bool sameStep(const std::optional<double>& a, const std::optional<double>& b) {
    if (!a || !b) return a == b;
    return std::abs(*a - *b) <= 1e-9 * std::max(std::abs(*a), std::abs(*b));
}

}  // namespace

RayModeSwitch switchRayMode(Scene& scene, const Series& shown, RayMode mode) {
    RayModeSwitch carried;
    if (mode == scene.rayMode) return carried;
    const OpacityWindow window = automaticOpacityWindow(shown);
    Scene current = scene;
    applyAutomaticRayToShown(current, shown, window, scene.rayMode);
    Scene next = scene;
    applyAutomaticRayToShown(next, shown, window, mode);
    scene.rayMode = mode;
    if (scene.stf == current.stf) {
        scene.stf = next.stf;
        carried.stf = true;
    }
    if (sameStep(scene.raycast.step, current.raycast.step)) {
        scene.raycast.step = next.raycast.step;
        carried.step = true;
    }
    auto& unchanged = scene.compositorOptions.unchanged;
    if (unchanged && current.compositorOptions.unchanged &&
        unchanged->opacity == current.compositorOptions.unchanged->opacity) {
        unchanged->opacity = next.compositorOptions.unchanged->opacity;
        carried.unchangedOpacity = true;
    }
    return carried;
}

}  // namespace tstyles
