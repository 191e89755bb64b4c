// The animations most movies need, made without hand-written keyframes: a focus group swept through
// time, exposure building up or a window of time-steps sliding, plain playback, and an orbit.
// `tstyles animate` offers them as options (--sweep-focus, --exposure, --playback, --orbit), the
// viewer as buttons.
#pragma once

#include <vector>

#include "tstyles/scene/animation.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

// The group's centre travels from the first time-step to the last: in whole steps (each time-step
// held for the same number of frames) or smoothly. InputError naming `field` when the curve has no
// node in that group.
AnimationTrack focusSweep(const Scene& scene, CurveName curve, NodeGroup group, int stepCount, int frames,
                          bool wholeSteps, const std::string& field);
// Exposure builds up: time-steps 0..0, 0..1, ..., 0..n-1, each held for the same number of frames.
std::vector<AnimationTrack> exposureBuildUp(int stepCount, int frames);
// A window of `window` time-steps slides from the first to the last.
std::vector<AnimationTrack> exposureWindow(int stepCount, int window, int frames);
// One time-step at a time (ordinary playback, for comparison).
std::vector<AnimationTrack> playback(int stepCount, int frames);
// The orbit camera turns by `degrees` about the vertical over the movie; the last frame stops one
// frame short of the turn, so a full turn loops without a repeated frame. InputError naming `field`
// for a look-at camera.
AnimationTrack orbitTurn(const Scene& scene, double degrees, int frames, const std::string& field);
// The orbit camera rises (or sinks) by `degrees` over the movie, eased in and out, stopping short
// of the poles (±89°).
AnimationTrack elevationChange(const Scene& scene, double degrees, int frames, const std::string& field);
// The orbit camera moves in from `distance` (where it stands at the start) to distance / factor,
// eased in and out; a factor below 1 moves out.
AnimationTrack zoomBy(const Scene& scene, double distance, double factor, int frames, const std::string& field);

}  // namespace tstyles
