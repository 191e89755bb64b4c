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

std::vector<Keyframe> readKeys(const JsonField& list) {
    if (list.arraySize() == 0) list.fail("needs at least one key [frame, value]");
    std::vector<Keyframe> keys;
    for (std::size_t i = 0; i < list.arraySize(); ++i) {
        const JsonField entry = list.element(i);
        if (!entry.isArray() || entry.arraySize() != 2) entry.fail("expected a key [frame, value], two numbers");
        Keyframe key;
        key.frame = entry.element(0).numberIn({0.0, double(kMostFrames)});
        key.value = entry.element(1).finiteNumber();
        if (!keys.empty() && key.frame <= keys.back().frame)
            entry.element(0).fail("frames must increase from key to key: " + formatNumber(key.frame) +
                                  " comes after " + formatNumber(keys.back().frame));
        keys.push_back(key);
    }
    return keys;
}

// Each key's value written into the scene and read back: a value the scene cannot take fails here,
// naming the key, rather than in the middle of a movie.
// The keys move the scene as read (defaults included), as sceneAtFrame will.
void checkValueKeys(const JsonField& track, const Scene& scene, const std::filesystem::path& origin,
                    const ValueTrackTarget& target, const std::vector<Keyframe>& keys) {
    const auto steps = parseJsonPath(target.path);
    if (!steps) track.failAt("value", "\"" + target.path + "\" is not a key path such as "
                                      "\"camera.orbit.azimuth_deg\" or \"stf.opacity[1].at\"");
    const std::filesystem::path folder =
        origin.empty() ? std::filesystem::current_path() : std::filesystem::absolute(origin).parent_path();
    Scene withoutAnimation = scene;
    withoutAnimation.animation = {};
    const json sceneJson = json::parse(sceneToJson(withoutAnimation, folder));
    const JsonField keyList = track.member("keys");
    for (std::size_t i = 0; i < keys.size(); ++i) {
        json moved = sceneJson;
        if (!setNumberAtPath(moved, *steps, keys[i].value))
            track.failAt("value", "the scene has no number at \"" + target.path + "\"");
        try {
            parseScene(moved.dump(), origin);
        } catch (const InputError& error) {
            std::string problem = error.what();
            if (const std::string prefix = origin.string() + ": "; problem.rfind(prefix, 0) == 0)
                problem.erase(0, prefix.size());
            keyList.element(i).fail("value " + formatNumber(keys[i].value) + " does not fit the scene: " + problem);
        }
    }
}

AnimationTrack readTrack(const JsonField& section, const Scene& scene, const std::filesystem::path& origin) {
    section.allowOnlyKeys({"value", "focus", "group", "keys", "interpolation"});
    AnimationTrack track;
    track.keys = readKeys(section.member("keys"));
    if (const auto interpolation = section.optionalMember("interpolation"))
        track.interpolation = interpolation->name<Interpolation>(interpolationFromString, interpolationNames());
    const std::optional<JsonField> valuePath = section.optionalMember("value");
    const std::optional<JsonField> focus = section.optionalMember("focus");
    if (bool(valuePath) == bool(focus))
        section.fail("needs exactly one of \"value\" (a key path of the scene) and \"focus\" (a curve)");
    if (valuePath) {
        if (section.optionalMember("group"))
            section.failAt("group", "belongs to a \"focus\" track, not a \"value\" track");
        const ValueTrackTarget target{valuePath->string()};
        checkValueKeys(section, scene, origin, target, track.keys);
        track.target = target;
        return track;
    }
    FocusTrackTarget target;
    target.curve = focus->name<CurveName>(curveNameFromString, curveNames());
    const JsonField group = section.member("group");
    target.group = group.integerIn(1, 1000000);
    if (!groupCentre(curveOf(scene, target.curve), target.group))
        group.fail("the curve " + toString(target.curve) + " has no node in group " + std::to_string(target.group));
    track.target = target;
    return track;
}

}  // namespace

Animation readAnimation(const JsonField& section, const Scene& scene, const std::filesystem::path& origin) {
    section.allowOnlyKeys({"frames", "fps", "tracks"});
    Animation animation;
    if (const auto fps = section.optionalMember("fps")) animation.framesPerSecond = fps->integerIn(1, 240);
    const JsonField tracks = section.member("tracks");
    if (tracks.arraySize() == 0) tracks.fail("needs at least one track");
    double lastKey = 0.0;
    for (std::size_t i = 0; i < tracks.arraySize(); ++i) {
        animation.tracks.push_back(readTrack(tracks.element(i), scene, origin));
        lastKey = std::max(lastKey, animation.tracks.back().keys.back().frame);
    }
    // Without "frames" the movie ends on the last key.
    animation.frames = int(std::floor(lastKey)) + 1;
    if (const auto frames = section.optionalMember("frames")) animation.frames = frames->integerIn(1, kMostFrames);
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
