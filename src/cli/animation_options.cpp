// `tstyles animate` presets: a movie from one option, no keyframes written by hand.
#include "animation_options.h"

#include <CLI/CLI.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/scene/animation_presets.h"

namespace tstyles::cli {
namespace {

// Frames a preset takes when --frames is not given: eight per time-step (three time-steps a second
// at 24 fps), and five seconds for camera moves alone.
constexpr int kFramesPerTimeStep = 8;
constexpr int kOrbitFrames = 120;

int windowOf(const std::string& exposure) {
    const std::string prefix = "window:";
    if (exposure.rfind(prefix, 0) != 0) throwInputError("", "--exposure", "expected grow or window:K, got \"" + exposure + "\"");
    try {
        std::size_t used = 0;
        const int window = std::stoi(exposure.substr(prefix.size()), &used);
        if (used == exposure.size() - prefix.size() && window >= 1) return window;
    } catch (const std::exception&) {
    }
    throwInputError("", "--exposure", "window:K needs a whole number K >= 1, got \"" + exposure + "\"");
}

}  // namespace

void addAnimationOptions(CLI::App& command, AnimationOptions& options) {
    command.add_option("--sweep-focus", options.sweepFocusGroup,
                       "Preset: the index TSTF's node group GROUP travels from the first time-step to the last")
        ->check(CLI::Range(1, 1000000));
    command.add_flag("--smooth", options.smooth, "With --sweep-focus: glide between time-steps instead of stepping");
    command.add_option("--exposure", options.exposure,
                       "Preset: 'grow' (time-steps 0..k, k growing: the multiple exposure builds up) or 'window:K' "
                       "(a window of K time-steps slides)");
    command.add_flag("--playback", options.playback, "Preset: one time-step at a time (ordinary playback)");
    command.add_option("--orbit", options.orbitDegrees, "Preset: the camera turns by DEGREES about the vertical");
    command.add_option("--elevation", options.elevationDegrees, "Preset: the camera rises by DEGREES (negative: sinks)");
    command.add_option("--zoom", options.zoomFactor, "Preset: the camera moves in by FACTOR (below 1: out)");
    command.add_option("--frames", options.frames, "Number of frames (default: the scene's, or the presets')")
        ->check(CLI::Range(1, 1000000));
    command.add_option("--fps", options.framesPerSecond, "Frames per second (default: the scene's, else 24)")
        ->check(CLI::Range(1, 240));
}

double cameraDistance(const SceneOnSeries& fitted) {
    const View view = resolveView(fitted.scene.camera, fitted.framed, fitted.series.worldBounds(), fitted.scene.width,
                                  fitted.scene.height);
    return glm::length(view.eye - view.target);
}

bool hasPreset(const AnimationOptions& options) {
    return options.sweepFocusGroup || options.exposure || options.playback || options.orbitDegrees ||
           options.elevationDegrees || options.zoomFactor;
}

Animation animationFor(const Scene& scene, std::size_t stepCount, const AnimationOptions& options,
                       const std::string& sceneName, double cameraDistance) {
    Animation animation = scene.animation;
    const bool anyPreset = hasPreset(options);
    if (!anyPreset && animation.empty())
        throwInputError(sceneName, "animation",
                        "the scene has no animation section; add one (docs/animation.md) or give a preset: "
                        "--sweep-focus GROUP, --exposure grow|window:K, --playback, --orbit DEGREES, --elevation "
                        "DEGREES or --zoom FACTOR");
    if (options.exposure && options.playback)
        throwInputError("", "--playback", "and --exposure both move the exposure; give one of them");
    if (anyPreset) {
        const int steps = int(stepCount);
        const bool stepped = options.sweepFocusGroup || options.exposure || options.playback;
        const int presetFrames = stepped ? kFramesPerTimeStep * steps : kOrbitFrames;
        animation.frames = options.frames.value_or(animation.empty() ? presetFrames : animation.frames);
        const int frames = animation.frames;
        if (options.sweepFocusGroup)
            animation.tracks.push_back(focusSweep(scene, CurveName::IndexTstf, *options.sweepFocusGroup, steps, frames,
                                                  !options.smooth, "--sweep-focus"));
        if (options.exposure) {
            const auto tracks = *options.exposure == "grow" ? exposureBuildUp(steps, frames)
                                                             : exposureWindow(steps, windowOf(*options.exposure), frames);
            animation.tracks.insert(animation.tracks.end(), tracks.begin(), tracks.end());
        }
        if (options.playback) {
            const auto tracks = playback(steps, frames);
            animation.tracks.insert(animation.tracks.end(), tracks.begin(), tracks.end());
        }
        if (options.orbitDegrees) animation.tracks.push_back(orbitTurn(scene, *options.orbitDegrees, frames, "--orbit"));
        if (options.elevationDegrees)
            animation.tracks.push_back(elevationChange(scene, *options.elevationDegrees, frames, "--elevation"));
        if (options.zoomFactor)
            animation.tracks.push_back(zoomBy(scene, cameraDistance, *options.zoomFactor, frames, "--zoom"));
    } else if (options.frames) {
        animation.frames = *options.frames;
    }
    if (options.framesPerSecond) animation.framesPerSecond = *options.framesPerSecond;
    return animation;
}

}  // namespace tstyles::cli
