// Keyframe interpolation and the scene at a frame of its animation.
#include "tstyles/scene/animation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "json_path.h"
#include "name_table.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/scene/scene.h"
#include "tstyles/scene/temporal_change.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/scene_keys.h"

namespace tstyles {
namespace {

constexpr std::array interpolationNameTable{
    std::pair{Interpolation::Linear, "linear"},
    std::pair{Interpolation::Smooth, "smooth"},
    std::pair{Interpolation::Constant, "constant"},
};
constexpr std::array curveNameTable{
    std::pair{CurveName::Stf, "stf"},
    std::pair{CurveName::IndexTstf, "tstf.index"},
    std::pair{CurveName::GradientTstf, "tstf.gradient"},
};

// Shifts every node of `group` by `offset`; positions stay inside [low, high] (the STF and the
// gradient TSTF are read over [0, 1]; index TSTF nodes may lie anywhere, the ends hold).
void moveGroup(TransferFunction1D& curve, NodeGroup group, double offset, double low, double high) {
    for (OpacityNode& node : curve.opacity)
        if (node.group == group) node.at = std::clamp(node.at + offset, low, high);
    for (ColorNode& node : curve.color)
        if (node.group == group) node.at = std::clamp(node.at + offset, low, high);
    curve.sortNodes();
}

// The InputError's text without the leading "FILE: " of the stand-in scene file.
std::string problemWithout(const std::string& message, const std::filesystem::path& origin) {
    const std::string prefix = origin.string() + ": ";
    return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

}  // namespace

std::string toString(Interpolation interpolation) { return nameOf(interpolationNameTable, interpolation); }
std::optional<Interpolation> interpolationFromString(const std::string& name) {
    return valueOf(interpolationNameTable, name);
}
std::vector<std::string> interpolationNames() { return allNames(interpolationNameTable); }
std::string toString(CurveName curve) { return nameOf(curveNameTable, curve); }
std::optional<CurveName> curveNameFromString(const std::string& name) { return valueOf(curveNameTable, name); }
std::vector<std::string> curveNames() { return allNames(curveNameTable); }

double AnimationTrack::valueAt(double frame) const {
    if (keys.empty()) return 0.0;
    if (frame <= keys.front().frame) return keys.front().value;
    if (frame >= keys.back().frame) return keys.back().value;
    const auto next = std::upper_bound(keys.begin(), keys.end(), frame,
                                       [](double f, const Keyframe& key) { return f < key.frame; });
    const Keyframe& before = *(next - 1);
    const Keyframe& after = *next;
    double t = (frame - before.frame) / (after.frame - before.frame);
    switch (interpolation) {
        case Interpolation::Constant: return before.value;
        case Interpolation::Smooth: t = t * t * (3.0 - 2.0 * t); break;
        case Interpolation::Linear: break;
    }
    return before.value + t * (after.value - before.value);
}

std::optional<double> groupCentre(const TransferFunction1D& curve, NodeGroup group) {
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (const OpacityNode& node : curve.opacity)
        if (node.group == group) low = std::min(low, node.at), high = std::max(high, node.at);
    for (const ColorNode& node : curve.color)
        if (node.group == group) low = std::min(low, node.at), high = std::max(high, node.at);
    if (low > high) return std::nullopt;
    return 0.5 * (low + high);
}

const TransferFunction1D& curveOf(const Scene& scene, CurveName curve) {
    switch (curve) {
        case CurveName::Stf: return scene.stf.curve;
        case CurveName::GradientTstf: return scene.gradientTstf.curve;
        case CurveName::IndexTstf: break;
    }
    return scene.indexTstf.curve;
}

TransferFunction1D& curveOf(Scene& scene, CurveName curve) {
    return const_cast<TransferFunction1D&>(curveOf(std::as_const(scene), curve));
}

Scene sceneAtFrame(const Scene& scene, int frame) {
    Scene result = scene;
    result.animation = {};
    bool anyValueTrack = false;
    for (const AnimationTrack& track : scene.animation.tracks) {
        const auto* focus = std::get_if<FocusTrackTarget>(&track.target);
        if (!focus) {
            anyValueTrack = true;
            continue;
        }
        TransferFunction1D& curve = curveOf(result, focus->curve);
        // The reader checked that the group exists; an edited scene may have lost it since.
        const std::optional<double> centre = groupCentre(curve, focus->group);
        if (!centre) continue;
        const bool unitAxis = focus->curve != CurveName::IndexTstf;
        moveGroup(curve, focus->group, track.valueAt(frame) - *centre, unitAxis ? 0.0 : -1e9, unitAxis ? 1.0 : 1e9);
    }
    if (!anyValueTrack) return result;

    // Keys of the table (scene_keys.h) are set in the scene directly, checked against their line;
    // the others (a node's position, a background channel) are written into the scene's own JSON,
    // which is read back, so every frame is checked like a scene file. The stand-in file sits in
    // the dataset's folder: relative paths resolve.
    const auto failAtFrame = [frame](const std::string& problem) {
        throw InputError("animation frame " + std::to_string(frame) + ": " + problem);
    };
    struct DirectValue {
        std::size_t track;
        const SceneKey* key;
        double value;
    };
    std::vector<DirectValue> direct;
    std::vector<std::pair<std::size_t, double>> throughJson;
    for (std::size_t i = 0; i < scene.animation.tracks.size(); ++i) {
        const AnimationTrack& track = scene.animation.tracks[i];
        const auto* target = std::get_if<ValueTrackTarget>(&track.target);
        if (!target) continue;
        const SceneKey* key = findSceneKey(target->path);
        const bool numeric = key && key->numeric;
        double value = track.valueAt(frame);
        if (numeric && key->numeric->whole) value = std::round(value);
        if (numeric)
            direct.push_back({i, key, value});
        else
            throughJson.emplace_back(i, value);
    }
    if (!throughJson.empty()) {
        const std::filesystem::path folder = userAbsolutePath({}, scene.dataset).parent_path();
        const std::filesystem::path origin = folder / "animated-scene.json";
        nlohmann::json root = nlohmann::json::parse(sceneToJson(result, folder));
        for (const auto& [index, value] : throughJson) {
            const std::string& path = std::get<ValueTrackTarget>(scene.animation.tracks[index].target).path;
            const auto steps = parseJsonPath(path);
            if (!steps || !setNumberAtPath(root, *steps, value))
                throwInputError("", "animation.tracks[" + std::to_string(index) + "].value",
                                "the scene has no number at \"" + path + "\"");
        }
        try {
            Scene moved = parseScene(root.dump(), origin);
            // A range or threshold fitted to the data ("auto", fitSceneToSeries) reads back unfitted: keep the fit.
            if (moved.gradientTstf.automaticRange && scene.gradientTstf.automaticRange) {
                moved.gradientTstf.rangeLow = scene.gradientTstf.rangeLow;
                moved.gradientTstf.rangeHigh = scene.gradientTstf.rangeHigh;
            }
            auto& movedUnchanged = moved.compositorOptions.unchanged;
            const auto& fittedUnchanged = scene.compositorOptions.unchanged;
            if (movedUnchanged && movedUnchanged->automatic && fittedUnchanged && fittedUnchanged->automatic)
                takeFit(*movedUnchanged, fittedOf(*fittedUnchanged));
            result = std::move(moved);
        } catch (const InputError& error) {
            failAtFrame(problemWithout(error.what(), origin));
        }
    }
    for (const DirectValue& entry : direct) {
        const NumericKey& key = *entry.key->numeric;
        const std::string path(entry.key->path);
        if (!std::isfinite(entry.value) || !key.range.contains(entry.value))
            failAtFrame(path + ": " + key.range.refusal(entry.value));
        if (!key.set(result, entry.value))
            throwInputError("", "animation.tracks[" + std::to_string(entry.track) + "].value",
                            "the scene has no number at \"" + path + "\"");
    }
    if (const auto problem = result.exposure.orderProblem()) failAtFrame("exposure.last: " + *problem);
    return result;
}

}  // namespace tstyles
