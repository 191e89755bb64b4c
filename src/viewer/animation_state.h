// The viewer's animation recording: keys recorded as whole scenes (the scene's animation section
// is made from them, so a saved scene animates headless alike), the frame previewed, and what the
// movie export asks and reports. Owned by ViewerApp, edited by the Animation section.
#pragma once

#include <string>
#include <vector>

#include "tstyles/scene/keyframe_recording.h"

namespace tstyles::viewer {

struct AnimationState {
    std::vector<RecordedKey> keys;  // sorted by frame
    int nextKeyFrame = 0;
    int framesPerSecond = 24;
    bool previewing = false;  // the volume shows the animation at previewFrame
    int previewFrame = 0;
    std::string moviePath;    // where Export writes; chosen from the scene file when empty
    std::string message;      // the last export's result or the last refusal
    double exportProgress = -1.0;  // < 0: no export running (ViewerApp reports it)

    // Records `scene` as the key at `frame` (replacing one there) and returns the scene's new
    // animation. InputError when the keys differ in more than numbers; the key is not kept then.
    Animation addKey(int frame, const Scene& scene);
    Animation removeKey(std::size_t index);
};

}  // namespace tstyles::viewer
