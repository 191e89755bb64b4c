// Preset animation tracks (focus sweep, exposure, playback, orbit).
#include "tstyles/scene/animation_presets.h"

#include <algorithm>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

// Values 0, 1, ..., count-1, each held for frames / count frames.
std::vector<Keyframe> heldSteps(int count, int frames, int offset = 0) {
    std::vector<Keyframe> keys;
    for (int i = 0; i < count; ++i) keys.push_back({double(i) * double(frames) / double(count), double(i + offset)});
    return keys;
}

AnimationTrack heldTrack(const std::string& path, int count, int frames, int offset = 0) {
    return {ValueTrackTarget{path}, heldSteps(count, frames, offset), Interpolation::Constant};
}

}  // namespace

AnimationTrack focusSweep(const Scene& scene, CurveName curve, NodeGroup group, int stepCount, int frames,
                          bool wholeSteps, const std::string& field) {
    if (!groupCentre(curveOf(scene, curve), group))
        throwInputError("", field, "the scene's " + toString(curve) + " has no node in group " + std::to_string(group));
    if (wholeSteps) return {FocusTrackTarget{curve, group}, heldSteps(stepCount, frames), Interpolation::Constant};
    const double lastFrame = std::max(frames - 1, 1);
    return {FocusTrackTarget{curve, group}, {{0.0, 0.0}, {lastFrame, double(stepCount - 1)}}, Interpolation::Linear};
}

std::vector<AnimationTrack> exposureBuildUp(int stepCount, int frames) {
    return {AnimationTrack{ValueTrackTarget{"exposure.first"}, {{0.0, 0.0}}, Interpolation::Constant},
            heldTrack("exposure.last", stepCount, frames)};
}

std::vector<AnimationTrack> exposureWindow(int stepCount, int window, int frames) {
    const int positions = std::max(stepCount - window + 1, 1);
    return {heldTrack("exposure.first", positions, frames),
            heldTrack("exposure.last", positions, frames, std::min(window, stepCount) - 1)};
}

std::vector<AnimationTrack> playback(int stepCount, int frames) {
    return {heldTrack("exposure.first", stepCount, frames), heldTrack("exposure.last", stepCount, frames)};
}

AnimationTrack orbitTurn(const Scene& scene, double degrees, int frames, const std::string& field) {
    const auto* orbit = std::get_if<OrbitCamera>(&scene.camera.pose);
    if (!orbit) throwInputError("", field, "needs an orbit camera; the scene's camera is look_at");
    return {ValueTrackTarget{"camera.orbit.azimuth_deg"},
            {{0.0, orbit->azimuthDeg}, {double(frames), orbit->azimuthDeg + degrees}},
            Interpolation::Linear};
}

AnimationTrack elevationChange(const Scene& scene, double degrees, int frames, const std::string& field) {
    const auto* orbit = std::get_if<OrbitCamera>(&scene.camera.pose);
    if (!orbit) throwInputError("", field, "needs an orbit camera; the scene's camera is look_at");
    const double end = std::clamp(orbit->elevationDeg + degrees, -89.0, 89.0);
    return {ValueTrackTarget{"camera.orbit.elevation_deg"},
            {{0.0, orbit->elevationDeg}, {double(std::max(frames - 1, 1)), end}},
            Interpolation::Smooth};
}

AnimationTrack zoomBy(const Scene& scene, double distance, double factor, int frames, const std::string& field) {
    if (!std::holds_alternative<OrbitCamera>(scene.camera.pose))
        throwInputError("", field, "needs an orbit camera; the scene's camera is look_at");
    if (!(factor > 0.0)) throwInputError("", field, "must be a factor > 0");
    return {ValueTrackTarget{"camera.orbit.distance"},
            {{0.0, distance}, {double(std::max(frames - 1, 1)), distance / factor}},
            Interpolation::Smooth};
}

}  // namespace tstyles
