// The "animation" section of a scene file, in and out (docs/animation.md): frames, rate and
// keyframed tracks, each key checked against the scene it moves, so a bad key fails on reading.
#include "scene_sections.h"

#include "json_path.h"
#include "tstyles/core/errors.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles {
namespace {

using nlohmann::json;

constexpr int kMostFrames = 1000000;

std::vector<Keyframe> readKeys(const JsonFieldReader& fields, const json& value, const std::string& path) {
    fields.expectArray(value, path);
    if (value.empty()) fields.fail(path, "needs at least one key [frame, value]");
    std::vector<Keyframe> keys;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string keyPath = elementPath(path, i);
        if (!value[i].is_array() || value[i].size() != 2)
            fields.fail(keyPath, "expected a key [frame, value], two numbers");
        Keyframe key;
        key.frame = fields.numberIn(value[i][0], elementPath(keyPath, 0), {0.0, double(kMostFrames)});
        key.value = fields.finiteNumber(value[i][1], elementPath(keyPath, 1));
        if (!keys.empty() && key.frame <= keys.back().frame)
            fields.fail(elementPath(keyPath, 0), "frames must increase from key to key: " + formatNumber(key.frame) +
                                                     " comes after " + formatNumber(keys.back().frame));
        keys.push_back(key);
    }
    return keys;
}

// Each key's value written into the scene and read back: a value the scene cannot take fails here,
// naming the key, rather than in the middle of a movie.
// The keys move the scene as read (defaults included), as sceneAtFrame will.
void checkValueKeys(const JsonFieldReader& fields, const Scene& scene, const std::filesystem::path& origin,
                    const std::string& trackPath, const ValueTrackTarget& target, const std::vector<Keyframe>& keys) {
    const auto steps = parseJsonPath(target.path);
    if (!steps) fields.fail(childPath(trackPath, "value"), "\"" + target.path + "\" is not a key path such as "
                                                           "\"camera.orbit.azimuth_deg\" or \"stf.opacity[1].at\"");
    const std::filesystem::path folder =
        origin.empty() ? std::filesystem::current_path() : std::filesystem::absolute(origin).parent_path();
    Scene withoutAnimation = scene;
    withoutAnimation.animation = {};
    const json sceneJson = json::parse(sceneToJson(withoutAnimation, folder));
    for (std::size_t i = 0; i < keys.size(); ++i) {
        json moved = sceneJson;
        if (!setNumberAtPath(moved, *steps, keys[i].value))
            fields.fail(childPath(trackPath, "value"), "the scene has no number at \"" + target.path + "\"");
        try {
            parseScene(moved.dump(), origin);
        } catch (const InputError& error) {
            std::string problem = error.what();
            if (const std::string prefix = origin.string() + ": "; problem.rfind(prefix, 0) == 0)
                problem.erase(0, prefix.size());
            fields.fail(elementPath(childPath(trackPath, "keys"), i), "value " + formatNumber(keys[i].value) +
                                                                          " does not fit the scene: " + problem);
        }
    }
}

AnimationTrack readTrack(const JsonFieldReader& fields, const json& value, const std::string& path,
                         const Scene& scene, const std::filesystem::path& origin) {
    fields.expectObject(value, path, {"value", "focus", "group", "keys", "interpolation"});
    AnimationTrack track;
    track.keys = readKeys(fields, fields.requiredMember(value, path, "keys"), childPath(path, "keys"));
    if (const json* interpolation = JsonFieldReader::member(value, "interpolation"))
        track.interpolation = fields.name<Interpolation>(*interpolation, childPath(path, "interpolation"),
                                                         interpolationFromString, interpolationNames());
    const json* valuePath = JsonFieldReader::member(value, "value");
    const json* focus = JsonFieldReader::member(value, "focus");
    if (bool(valuePath) == bool(focus))
        fields.fail(path, "needs exactly one of \"value\" (a key path of the scene) and \"focus\" (a curve)");
    if (valuePath) {
        if (JsonFieldReader::member(value, "group"))
            fields.fail(childPath(path, "group"), "belongs to a \"focus\" track, not a \"value\" track");
        const ValueTrackTarget target{fields.string(*valuePath, childPath(path, "value"))};
        checkValueKeys(fields, scene, origin, path, target, track.keys);
        track.target = target;
        return track;
    }
    FocusTrackTarget target;
    target.curve = fields.name<CurveName>(*focus, childPath(path, "focus"), curveNameFromString, curveNames());
    target.group = fields.integerIn(fields.requiredMember(value, path, "group"), childPath(path, "group"), 1, 1000000);
    if (!groupCentre(curveOf(scene, target.curve), target.group))
        fields.fail(childPath(path, "group"), "the curve " + toString(target.curve) + " has no node in group " +
                                                  std::to_string(target.group));
    track.target = target;
    return track;
}

}  // namespace

Animation readAnimation(const JsonFieldReader& fields, const json& value, const Scene& scene,
                        const std::filesystem::path& origin) {
    const std::string path = "animation";
    fields.expectObject(value, path, {"frames", "fps", "tracks"});
    Animation animation;
    if (const json* fps = JsonFieldReader::member(value, "fps"))
        animation.framesPerSecond = fields.integerIn(*fps, childPath(path, "fps"), 1, 240);
    const json& tracks = fields.requiredMember(value, path, "tracks");
    fields.expectArray(tracks, childPath(path, "tracks"));
    if (tracks.empty()) fields.fail(childPath(path, "tracks"), "needs at least one track");
    double lastKey = 0.0;
    for (std::size_t i = 0; i < tracks.size(); ++i) {
        animation.tracks.push_back(readTrack(fields, tracks[i], elementPath(childPath(path, "tracks"), i), scene,
                                             origin));
        lastKey = std::max(lastKey, animation.tracks.back().keys.back().frame);
    }
    // Without "frames" the movie ends on the last key.
    animation.frames = int(std::floor(lastKey)) + 1;
    if (const json* frames = JsonFieldReader::member(value, "frames"))
        animation.frames = fields.integerIn(*frames, childPath(path, "frames"), 1, kMostFrames);
    return animation;
}

}  // namespace tstyles

namespace tstyles {

nlohmann::ordered_json animationJson(const Animation& animation) {
    nlohmann::ordered_json result;
    result["frames"] = animation.frames;
    result["fps"] = animation.framesPerSecond;
    nlohmann::ordered_json tracks = nlohmann::ordered_json::array();
    for (const AnimationTrack& track : animation.tracks) {
        nlohmann::ordered_json entry;
        if (const auto* value = std::get_if<ValueTrackTarget>(&track.target)) {
            entry["value"] = value->path;
        } else {
            const auto& focus = std::get<FocusTrackTarget>(track.target);
            entry["focus"] = toString(focus.curve);
            entry["group"] = focus.group;
        }
        entry["interpolation"] = toString(track.interpolation);
        nlohmann::ordered_json keys = nlohmann::ordered_json::array();
        for (const Keyframe& key : track.keys) keys.push_back(nlohmann::ordered_json::array({key.frame, key.value}));
        entry["keys"] = keys;
        tracks.push_back(entry);
    }
    result["tracks"] = tracks;
    return result;
}

}  // namespace tstyles
