// Recording and removing keys.
#include "animation_state.h"

#include <algorithm>

namespace tstyles::viewer {

Animation AnimationState::addKey(int frame, const Scene& scene) {
    std::vector<RecordedKey> next = keys;
    next.erase(std::remove_if(next.begin(), next.end(), [frame](const RecordedKey& key) { return key.frame == frame; }),
               next.end());
    RecordedKey key{frame, scene};
    key.scene.animation = {};
    next.push_back(std::move(key));
    std::sort(next.begin(), next.end(), [](const RecordedKey& a, const RecordedKey& b) { return a.frame < b.frame; });
    Animation animation = animationFromRecordedKeys(next, framesPerSecond);  // throws before `keys` changes
    keys = std::move(next);
    return animation;
}

Animation AnimationState::removeKey(std::size_t index) {
    keys.erase(keys.begin() + std::ptrdiff_t(index));
    return animationFromRecordedKeys(keys, framesPerSecond);
}

}  // namespace tstyles::viewer
