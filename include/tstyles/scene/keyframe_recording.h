// Keyframes recorded as whole scenes (the viewer's "add key at this frame") turned into an
// animation: every number of the scene that differs between keys becomes a track through those
// keys, so a recorded movie is an ordinary `animation` section (docs/animation.md).
#pragma once

#include <vector>

#include "tstyles/scene/scene.h"

namespace tstyles {

struct RecordedKey {
    int frame = 0;
    Scene scene;  // its own animation is ignored
};

// `keys` in any order, frames distinct. The keys must share the scene's shape (the same nodes,
// camera kind and sections): a key with a node added or removed is an InputError saying which
// keys differ, since only numbers move between keys. The movie ends on the last key's frame.
Animation animationFromRecordedKeys(std::vector<RecordedKey> keys, int framesPerSecond);

}  // namespace tstyles
