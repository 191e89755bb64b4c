// The frame options of the CLI's renders of many frames with one renderer (animate's frames,
// check's cases): styles take their gradients with six fetches, as `tstyles render` draws its one
// frame. The gradient atlas, which the renderer reads from a series' second styled frame on, would
// make an image depend on the frames drawn before it: a movie's later frames would differ from its
// first and from `render --frame N` (up to 7/255 on the hurricane), a suite's cases from the suite's
// order and the --jobs split (up to 3/255 on the styled super-ellipsoid).
#pragma once

#include "tstyles/render/renderer.h"

namespace tstyles::cli {

inline FrameOptions asOneFrameRenderDrawsIt() {
    FrameOptions options;
    options.precomputedGradients = false;
    return options;
}

}  // namespace tstyles::cli
