// The scene file's "ray": a mode's name ("maximum"), or an object with the mode and its options
// ({"mode": "isosurface", "values": [0.3, 0.6], "opacities": [0.4, 1]}). Absent: composite.
#include "scene_sections.h"
#include "tstyles/scene/ray_modes.h"

namespace tstyles {
namespace {

using nlohmann::ordered_json;

RayModeOptionValue readOption(const RayModeOption& option, const JsonField& field) {
    if (option.kind == RayModeOptionKind::Number) return field.numberIn(option.range);
    if (!field.isArray()) field.fail("expected an array of 1 to " + std::to_string(option.maxCount) +
                                     " numbers, got " + field.typeWithArticle());
    const std::size_t count = field.arraySize();
    if (count < 1 || count > option.maxCount)
        field.fail("expected 1 to " + std::to_string(option.maxCount) + " numbers, got " + std::to_string(count));
    return field.numbers(count, option.range);
}

}  // namespace

void readRay(const JsonField& section, Scene& scene) {
    if (section.isString()) {
        scene.rayMode = section.name<RayMode>(rayModeFromString, rayModeNames());
        return;
    }
    if (!section.isObject())
        section.fail("expected a name or an object, got " + std::string(section.value().type_name()));
    // Every mode's options, so that one of another mode is refused as not taken.
    std::vector<std::string_view> keys = {"mode"};
    for (const RayModeOption* option : rayModeOptionsOfAll()) keys.emplace_back(option->key);
    section.allowOnlyKeys(keys);
    scene.rayMode = section.member("mode").name<RayMode>(rayModeFromString, rayModeNames());
    const RayModeInfo& info = rayModeInfo(scene.rayMode);
    for (const RayModeOption* known : rayModeOptionsOfAll()) {
        const std::optional<JsonField> given = section.optionalMember(known->key);
        if (!given) continue;
        const RayModeOption* option = info.options.find(known->key);
        if (!option) given->fail(std::string(info.name) + " takes no " + known->key);
        scene.rayOptions.values[option->key] = readOption(*option, *given);
    }
    for (const RayModeOption& option : info.options) {
        if (!option.countOf) continue;
        const std::size_t count = scene.rayOptions.numbers(option).size();
        const std::size_t wanted = scene.rayOptions.numbers(*info.options.find(option.countOf)).size();
        if (count != wanted)
            section.failAt(option.key, "has " + std::to_string(count) + " entries, one for each of the " +
                                           std::to_string(wanted) + " " + option.countOf);
    }
}

std::optional<ordered_json> rayJson(const Scene& scene) {
    const RayModeInfo& info = rayModeInfo(scene.rayMode);
    if (scene.rayMode == kCompositeRay) return std::nullopt;  // the default: files stay as they were
    if (info.options.empty()) return ordered_json(info.name);
    ordered_json object;
    object["mode"] = info.name;
    for (const RayModeOption& option : info.options)
        object[option.key] = option.kind == RayModeOptionKind::Number ? ordered_json(scene.rayOptions.number(option))
                                                                      : ordered_json(scene.rayOptions.numbers(option));
    return object;
}

}  // namespace tstyles
