// Recorded key scenes to value tracks: the numbers of each key's scene JSON, compared path by path.
#include "tstyles/scene/keyframe_recording.h"

#include <algorithm>
#include <map>

#include <nlohmann/json.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles {
namespace {

using nlohmann::json;

// Every number under `value`, by the path the scene format's messages use; other leaves by a
// marker of their text, so that a changed name or style also shows as a different shape.
void flatten(const json& value, const std::string& path, std::map<std::string, json>& leaves) {
    if (value.is_object()) {
        for (auto member = value.begin(); member != value.end(); ++member)
            flatten(*member, path.empty() ? member.key() : path + "." + member.key(), leaves);
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i) flatten(value[i], path + "[" + std::to_string(i) + "]", leaves);
    } else {
        leaves[path] = value;
    }
}

std::map<std::string, json> leavesOf(const Scene& scene) {
    Scene still = scene;
    still.animation = {};
    const std::filesystem::path folder = userAbsolutePath({}, scene.dataset).parent_path();
    std::map<std::string, json> leaves;
    flatten(json::parse(sceneToJson(still, folder)), "", leaves);
    return leaves;
}

}  // namespace

Animation animationFromRecordedKeys(std::vector<RecordedKey> keys, int framesPerSecond) {
    Animation animation;
    animation.framesPerSecond = framesPerSecond;
    if (keys.empty()) return animation;
    std::sort(keys.begin(), keys.end(), [](const RecordedKey& a, const RecordedKey& b) { return a.frame < b.frame; });
    std::vector<std::map<std::string, json>> leaves;
    for (const RecordedKey& key : keys) leaves.push_back(leavesOf(key.scene));
    for (std::size_t k = 1; k < keys.size(); ++k) {
        if (keys[k].frame == keys[k - 1].frame)
            throwInputError("", "keyframes", "two keys at frame " + std::to_string(keys[k].frame));
        for (const auto& [path, value] : leaves[0]) {
            const auto other = leaves[k].find(path);
            const bool sameShape = other != leaves[k].end() && other->second.is_number() == value.is_number() &&
                                   (value.is_number() || other->second == value);
            if (!sameShape || leaves[k].size() != leaves[0].size())
                throwInputError("", "keyframes",
                                "the key at frame " + std::to_string(keys[k].frame) + " differs from the key at frame " +
                                    std::to_string(keys[0].frame) + " in more than numbers (at " + path +
                                    "): keys may move values, not add or remove nodes or change names");
        }
    }
    for (const auto& [path, value] : leaves[0]) {
        if (!value.is_number()) continue;
        AnimationTrack track{ValueTrackTarget{path}, {}, Interpolation::Linear};
        bool moves = false;
        for (std::size_t k = 0; k < keys.size(); ++k) {
            const double number = leaves[k].at(path).get<double>();
            moves = moves || number != value.get<double>();
            track.keys.push_back({double(keys[k].frame), number});
        }
        if (moves) animation.tracks.push_back(std::move(track));
    }
    animation.frames = keys.back().frame + 1;
    // A single key, or keys that differ in nothing, still make a (still) movie of that length.
    if (animation.tracks.empty())
        animation.tracks.push_back({ValueTrackTarget{"camera.fov_deg"}, {{0.0, keys[0].scene.camera.fovDeg}}});
    return animation;
}

}  // namespace tstyles
