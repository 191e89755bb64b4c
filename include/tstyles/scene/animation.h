// Animation sequences (the paper's focus and exposure animations): keyframed tracks that move
// values of a scene from frame to frame. GL-free; `tstyles animate` and the viewer render the scenes
// that sceneAtFrame makes (format: docs/animation.md).
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "tstyles/scene/transfer_function.h"

namespace tstyles {

struct Scene;

// How a track moves between two keys: straight, eased in and out, or held until the next key.
enum class Interpolation { Linear, Smooth, Constant };
std::string toString(Interpolation interpolation);  // "linear", "smooth", "constant"
std::optional<Interpolation> interpolationFromString(const std::string& name);
std::vector<std::string> interpolationNames();

struct Keyframe {
    double frame = 0.0;  // frames count from 0; keys may lie past the last frame (a loop's end)
    double value = 0.0;
    bool operator==(const Keyframe&) const = default;
};

// Any number of the scene file, named by its path as error messages spell it
// ("camera.orbit.azimuth_deg", "stf.opacity[2].at", "exposure.last"). Integer keys round.
struct ValueTrackTarget {
    std::string path;
    bool operator==(const ValueTrackTarget&) const = default;
};

// A node group of one curve, moved as a whole: the value is where the group's centre (the middle of
// its nodes' positions) lies, in the curve's units (time-steps for the index TSTF).
enum class CurveName { Stf, IndexTstf, GradientTstf };
std::string toString(CurveName curve);  // "stf", "tstf.index", "tstf.gradient"
std::optional<CurveName> curveNameFromString(const std::string& name);
std::vector<std::string> curveNames();
struct FocusTrackTarget {
    CurveName curve = CurveName::IndexTstf;
    NodeGroup group = 1;
    bool operator==(const FocusTrackTarget&) const = default;
};

struct AnimationTrack {
    std::variant<ValueTrackTarget, FocusTrackTarget> target;
    std::vector<Keyframe> keys;  // in increasing frame order, at least one
    Interpolation interpolation = Interpolation::Linear;
    bool operator==(const AnimationTrack&) const = default;
    // The track's value at `frame`: the first key's before it, the last key's after it.
    double valueAt(double frame) const;
};

struct Animation {
    int frames = 0;  // 0: the scene has no animation
    int framesPerSecond = 24;
    std::vector<AnimationTrack> tracks;
    bool operator==(const Animation&) const = default;
    bool empty() const { return frames == 0; }
};

// The scene at `frame` of its animation (tracks applied in order; the result has no animation).
// Value tracks go through the scene's JSON, so the frame is checked like a scene file: an
// InputError names the track and the key's path where a value leaves its allowed range.
Scene sceneAtFrame(const Scene& scene, int frame);

// The centre of a group's nodes on a curve; none when the curve has no node in that group.
std::optional<double> groupCentre(const TransferFunction1D& curve, NodeGroup group);
const TransferFunction1D& curveOf(const Scene& scene, CurveName curve);
TransferFunction1D& curveOf(Scene& scene, CurveName curve);

}  // namespace tstyles
