// The command-line presets of `tstyles animate` (--sweep-focus, --exposure, --playback, --orbit)
// and the movie settings (--frames, --fps): turned into the scene's animation section.
#pragma once

#include <optional>
#include <string>

#include "cli11_forward.h"

#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/scene.h"

namespace tstyles::cli {

struct AnimationOptions {
    std::optional<int> sweepFocusGroup;   // --sweep-focus GROUP (index TSTF)
    bool smooth = false;                  // --smooth: the focus glides instead of stepping
    std::optional<std::string> exposure;  // --exposure grow|window:K
    bool playback = false;                // --playback
    std::optional<double> orbitDegrees;   // --orbit DEGREES
    std::optional<double> elevationDegrees;  // --elevation DEGREES
    std::optional<double> zoomFactor;     // --zoom FACTOR
    std::optional<int> frames;            // --frames
    std::optional<int> framesPerSecond;   // --fps
};
void addAnimationOptions(CLI::App& command, AnimationOptions& options);
bool hasPreset(const AnimationOptions& options);

// Where the scene's camera stands from its target, resolved against the fitted series.
double cameraDistance(const SceneOnSeries& fitted);

// The scene's animation with the presets' tracks added, frames and rate as the options say. A
// scene with no animation and no preset is an InputError naming `sceneName`. `cameraDistance` is
// where the orbit camera stands (resolved against the series): where --zoom starts.
Animation animationFor(const Scene& scene, std::size_t stepCount, const AnimationOptions& options,
                       const std::string& sceneName, double cameraDistance);

}  // namespace tstyles::cli
