// The table of scene keys (scene_keys.h) and the documentation's table made from it.
#include "tstyles/scene/scene_keys.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include "tstyles/data/format_listing.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

// The orbit of a scene whose camera is one, else null.
const OrbitCamera* orbitOf(const Scene& s) { return std::get_if<OrbitCamera>(&s.camera.pose); }
OrbitCamera* orbitOf(Scene& s) { return std::get_if<OrbitCamera>(&s.camera.pose); }

// A number of the orbit: none, and not set, where the camera is a look_at.
template <double OrbitCamera::*number>
std::optional<double> orbitNumber(const Scene& s) {
    const OrbitCamera* orbit = orbitOf(s);
    return orbit ? std::optional<double>(orbit->*number) : std::nullopt;
}

template <double OrbitCamera::*number>
bool setOrbitNumber(Scene& s, double value) {
    OrbitCamera* orbit = orbitOf(s);
    if (orbit) orbit->*number = value;
    return orbit != nullptr;
}

// A number of the unchanged places that "auto" fits: none, and not set, without unchanged places or
// where they are fitted.
template <double UnchangedTime::*number>
std::optional<double> fittedUnchanged(const Scene& s) {
    const auto& unchanged = s.compositorOptions.unchanged;
    return unchanged && !unchanged->automatic ? std::optional<double>(*unchanged.*number) : std::nullopt;
}

template <double UnchangedTime::*number>
bool setFittedUnchanged(Scene& s, double value) {
    auto& unchanged = s.compositorOptions.unchanged;
    if (!unchanged || unchanged->automatic) return false;
    *unchanged.*number = value;
    return true;
}

std::vector<std::string> quotedNames(std::vector<std::string> names) {
    for (std::string& name : names) name = "\"" + name + "\"";
    return names;
}

// The lines of the compositors' options, from their table: "compositor.threshold", ...
std::vector<SceneKey> compositorOptionKeys() {
    std::vector<SceneKey> keys;
    for (const CompositorOption* option : compositorOptionsOfAll()) {
        const std::string key = option->key;
        const std::string takers = listedNames(compositorsTaking(key), "`") + " only: " + option->help;
        switch (option->kind) {
            case CompositorOptionKind::Number:
                keys.push_back({"compositor." + key, "number", "`" + formatNumber(option->defaultNumber) + "`", takers,
                                NumericKey{false, option->range,
                                           [option](const Scene& s) -> std::optional<double> {
                                               if (!compositorInfo(s.compositor).options.find(option->key))
                                                   return std::nullopt;
                                               return s.compositorOptions.number(*option);
                                           },
                                           [option](Scene& s, double v) {
                                               if (!compositorInfo(s.compositor).options.find(option->key))
                                                   return false;
                                               s.compositorOptions.values[option->key] = v;
                                               return true;
                                           }}});
                break;
            case CompositorOptionKind::TimeStepPair:
                keys.push_back({"compositor." + key, "2 integers `[from, to]`", "first and last time-step",
                                "whole time-step indices of the series (checked when the scene meets it); " + takers,
                                std::nullopt});
                break;
            case CompositorOptionKind::Choice:
                keys.push_back({"compositor." + key, "string", "`\"" + std::string(option->choices[0]) + "\"`",
                                listedNames(quotedNames(option->choiceNames()), "`") + "; " + takers, std::nullopt});
                break;
        }
    }
    return keys;
}

// The lines of "ray" and its modes' options, from the table of ray modes: "ray.attenuation", ...
std::vector<SceneKey> rayModeKeys() {
    std::vector<SceneKey> keys = {
        {"ray", "string or object", "`\"composite\"`",
         "how the samples along a ray become the pixel: a name, " + listedNames(quotedNames(rayModeNames()), "`") +
             " (docs/ray-modes.md); or an object, below",
         std::nullopt},
        {"ray.mode", "string", "", "one of the names; with the options it takes", std::nullopt},
    };
    for (const RayModeOption* option : rayModeOptionsOfAll()) {
        const std::string key = option->key;
        const std::string takers = listedNames(rayModesTaking(key), "`") + " only: " + option->help;
        if (option->kind == RayModeOptionKind::NumberList) {
            keys.push_back({"ray." + key, "1 to " + std::to_string(option->maxCount) + " numbers",
                            option->countOf ? "`" + formatNumber(option->defaultNumber) + "` for each of `" +
                                                  option->countOf + "`"
                                            : "`[" + formatNumber(option->defaultNumber) + "]`",
                            "each " + option->range.describe() + "; " + takers, std::nullopt});
            continue;
        }
        keys.push_back({"ray." + key, "number", "`" + formatNumber(option->defaultNumber) + "`", takers,
                        NumericKey{false, option->range,
                                   [option](const Scene& s) -> std::optional<double> {
                                       if (!rayModeInfo(s.rayMode).options.find(option->key)) return std::nullopt;
                                       return s.rayOptions.number(*option);
                                   },
                                   [option](Scene& s, double v) {
                                       if (!rayModeInfo(s.rayMode).options.find(option->key)) return false;
                                       s.rayOptions.values[option->key] = v;
                                       return true;
                                   }}});
    }
    return keys;
}

const std::vector<SceneKey>& keyTable() {
    static const std::vector<SceneKey> keys = [] {
        std::vector<SceneKey> table = {
            {"dataset", "string", "— (required)",
             "a path to a series manifest, or a file the readers open (" + seriesFormatNames() +
                 "; docs/readers.md, read with `render`'s `--var`, `--steps`, ... options); relative paths start at "
                 "the scene file's folder",
             std::nullopt},
            {"orientation", "string or 3 strings", "`\"data\"`",
             "`\"data\"` (axes as stored), `\"auto\"` (from what the file says its axes mean: "
             "docs/automatic-scene.md), or the data axes shown as right, up and toward the viewer, e.g. "
             "`[\"+x\", \"+z\", \"-y\"]` (no axis twice, not mirrored)",
             std::nullopt},
            {"aspect", "string or 3 numbers", "`\"physical\"`",
             "`\"physical\"` (each axis in its unit; lengths of different units in the smallest), `\"cubic\"` "
             "(every axis as long as the longest), `\"auto\"` (physical, or a map: docs/automatic-scene.md), "
             "or a scale per display axis `[sx, sy, sz]`, each > 0",
             std::nullopt},
            {"vertical_exaggeration", "number or `\"auto\"`", "`1`",
             "multiplies the display's vertical (y) scale; `\"auto\"`: 1, or for a map the factor that makes "
             "the height a quarter of the width",
             NumericKey{false, aboveZero,
                        [](const Scene& s) -> std::optional<double> {
                            return s.display.verticalExaggeration;
                        },
                        [](Scene& s, double v) {
                            if (!s.display.verticalExaggeration) return false;
                            s.display.verticalExaggeration = v;
                            return true;
                        }}},
            {"image.width", "integer", "`512`",
             "",
             NumericKey{true, Interval{1.0, 16384.0},
                        [](const Scene& s) -> std::optional<double> {
                            return double(s.width);
                        },
                        [](Scene& s, double v) { s.width = int(v); return true; }}},
            {"image.height", "integer", "`512`",
             "",
             NumericKey{true, Interval{1.0, 16384.0},
                        [](const Scene& s) -> std::optional<double> {
                            return double(s.height);
                        },
                        [](Scene& s, double v) { s.height = int(v); return true; }}},
            {"image.background", "4 numbers (RGBA)", "`[0, 0, 0, 1]`",
             "each in [0, 1]",
             std::nullopt},
            {"camera.orbit", "object", "orbit with the defaults below",
             "exactly one of `orbit`, `look_at` (neither: default orbit)",
             std::nullopt},
            {"camera.orbit.target", "3 numbers", "centre of the series' bounds",
             "finite",
             std::nullopt},
            {"camera.orbit.distance", "number", "frames the series (see below)",
             "",
             NumericKey{false, aboveZero,
                        [](const Scene& s) -> std::optional<double> {
                            const OrbitCamera* o = orbitOf(s);
                            return o && o->distance ? std::optional<double>(*o->distance) : std::nullopt;
                        },
                        [](Scene& s, double v) {
                            OrbitCamera* orbit = orbitOf(s);
                            if (orbit) orbit->distance = v;
                            return orbit != nullptr;
                        }}},
            {"camera.orbit.azimuth_deg", "number", "`30`",
             "turns from +z toward +x",
             NumericKey{false, anyFinite, orbitNumber<&OrbitCamera::azimuthDeg>,
                        setOrbitNumber<&OrbitCamera::azimuthDeg>}},
            {"camera.orbit.elevation_deg", "number", "`20`",
             "lifts from the xz-plane toward +y",
             NumericKey{false, Interval{-90.0, 90.0}, orbitNumber<&OrbitCamera::elevationDeg>,
                        setOrbitNumber<&OrbitCamera::elevationDeg>}},
            {"camera.look_at.eye", "3 numbers", "— (required in `look_at`)",
             "finite, different from `target`",
             std::nullopt},
            {"camera.look_at.target", "3 numbers", "— (required in `look_at`)",
             "finite",
             std::nullopt},
            {"camera.look_at.up", "3 numbers", "`[0, 1, 0]`",
             "finite, non-zero, not parallel to `target - eye`",
             std::nullopt},
            {"camera.frame", "string", "`\"series\"`",
             "what an orbit without `target` or `distance` frames: `\"series\"` (its whole bounds), "
             "`\"visible\"` (the part the STF gives any opacity)",
             std::nullopt},
            {"camera.fov_deg", "number", "`30`",
             "",
             NumericKey{false, Interval{0.0, 180.0, false, false},
                        [](const Scene& s) -> std::optional<double> {
                            return s.camera.fovDeg;
                        },
                        [](Scene& s, double v) { s.camera.fovDeg = v; return true; }}},
            {"camera.projection", "string", "`\"perspective\"`",
             "`\"perspective\"`, `\"orthographic\"`",
             std::nullopt},
            {"raycast.step", "number", "half the finest voxel spacing",
             "world units",
             NumericKey{false, aboveZero,
                        [](const Scene& s) -> std::optional<double> {
                            return s.raycast.step;
                        },
                        [](Scene& s, double v) { s.raycast.step = v; return true; }}},
            {"raycast.termination", "number", "`0.99`",
             "rays stop at this accumulated opacity",
             NumericKey{false, Interval{0.0, 1.0, false, true},
                        [](const Scene& s) -> std::optional<double> {
                            return s.raycast.termination;
                        },
                        [](Scene& s, double v) { s.raycast.termination = v; return true; }}},
            {"stf.opacity", "array of `{\"at\", \"opacity\"}`", "`[{0, 0}, {1, 1}]` (a ramp)",
             "`at` in [0, 1], `opacity` in [0, 1]",
             std::nullopt},
            {"stf.color", "array of `{\"at\", \"color\"}`", "`[{0, [1, 1, 1]}]` (white)",
             "`at` in [0, 1], each component in [0, 1]",
             std::nullopt},
            {"compositor", "string or object", "`\"temporal-mip\"`",
             "a name: " + listedNames(quotedNames(temporalCompositorNames()), "`") +
                 " (docs/compositors.md); or an object, below",
             std::nullopt},
            {"compositor.name", "string", "",
             "one of the names; with the options it takes",
             std::nullopt},
            {"compositor.unchanged", "object", "absent: time colours everywhere",
             "the compositors that pick a time-step (" + listedNames(compositorsTakingUnchanged(), "`") +
                 "): no time colour where a place's densities change by no more than "
             "`below`, nor where two time-steps tie within `tie` (docs/compositors.md, \"Unchanged places\"); "
             "the automatic scene has `{\"below\": \"auto\", \"opacity\": 0.35}`",
             std::nullopt},
            {"compositor.unchanged.below", "number or `\"auto\"`", "`\"auto\"`",
             "a change in density units; `\"auto\"` fits `below`, `tie`, `gain` and `boundary` to the data "
             "whenever the scene meets a series (docs/automatic-scene.md)",
             NumericKey{false, unitInterval, fittedUnchanged<&UnchangedTime::below>,
                        setFittedUnchanged<&UnchangedTime::below>}},
            {"compositor.unchanged.tie", "number", "`0`",
             "with a number for `below`: a difference in density units up to which two time-steps tie",
             NumericKey{false, unitInterval, fittedUnchanged<&UnchangedTime::tie>,
                        setFittedUnchanged<&UnchangedTime::tie>}},
            {"compositor.unchanged.gain", "number", "`1`",
             "with a number for `below`: places whose time shows are as opaque as a slab this many times as "
             "thick",
             NumericKey{false, Interval{1.0, 8.0}, fittedUnchanged<&UnchangedTime::gain>,
                        setFittedUnchanged<&UnchangedTime::gain>}},
            {"compositor.unchanged.boundary", "number", "`0`",
             "with a number for `below`: a value gradient (density per display length); unchanged places keep "
             "their whole share where the gradient is as steep and a quarter of it where the value is flat; "
             "0: the whole share everywhere",
             NumericKey{false, Interval{0.0, std::numeric_limits<double>::infinity()},
                        fittedUnchanged<&UnchangedTime::boundary>,
                        setFittedUnchanged<&UnchangedTime::boundary>}},
            {"compositor.unchanged.opacity", "number", "`1`",
             "the share of the STF's opacity that places without time colour keep: 0 transparent",
             NumericKey{false, unitInterval,
                        [](const Scene& s) -> std::optional<double> {
                            const auto& u = s.compositorOptions.unchanged;
                            return u ? std::optional<double>(u->opacity) : std::nullopt;
                        },
                        [](Scene& s, double v) {
                            auto& u = s.compositorOptions.unchanged;
                            if (u) u->opacity = v;
                            return u.has_value();
                        }}},
            {"compositor.glsl", "string", "",
             "the scene's own compositor: a GLSL function body (docs/compositors.md), checked by the sandbox "
             "on reading; no `name` with it",
             std::nullopt},
            {"compositor.file", "string", "",
             "the same in a file, relative to the scene file's folder; instead of `glsl`, and written back as "
             "the same file",
             std::nullopt},
            {"compositor.reads", "string", "",
             "with `glsl` or `file`, required: `\"index-tstf\"` (the code returns a time-step index) or "
             "`\"gradient-tstf\"` (a value)",
             std::nullopt},
            {"tstf.index.opacity", "array of `{\"at\", \"opacity\"}`", "`[{0, 1}]` (opaque)",
             "`at` in time-steps (any finite number: a focus swept to step 0 has nodes before it), `opacity` "
             "in [0, 1]",
             std::nullopt},
            {"tstf.index.color", "array of `{\"at\", \"color\"}`", "`[{0, [1, 1, 1]}]` (white)",
             "`at` in time-steps (any finite number), components in [0, 1]",
             std::nullopt},
            {"tstf.gradient.range", "2 numbers `[low, high]`, or `\"auto\"`", "`[0, 1]`",
             "low < high, in density units (a trend: per unit of time); negative for signed compositors "
             "(`linear-trend`, `difference`); `\"auto\"`: fitted to the compositor whenever the scene meets a "
             "series, from C, the 99th percentile of the change over time at the places the STF shows: [0, "
             "C], [0, C / 2] for `temporal-std-dev`, [-C, C] for `difference`, [-C / T, C / T] for "
             "`linear-trend` over the series' time span T (docs/compositors.md)",
             std::nullopt},
            {"tstf.gradient.opacity", "array of `{\"at\", \"opacity\"}`", "`[{0, 1}]` (opaque)",
             "`at` in [0, 1], `opacity` in [0, 1]",
             std::nullopt},
            {"tstf.gradient.color", "array of `{\"at\", \"color\"}`", "`[{0, [1, 1, 1]}]` (white)",
             "`at` in [0, 1], components in [0, 1]",
             std::nullopt},
            {"final", "string", "`\"modulate\"`",
             "`\"stf\"`, `\"tstf\"`, `\"modulate\"`",
             std::nullopt},
            {"exposure.first", "integer", "`0`",
             "the first time-step that takes part in the image (the paper's multiple exposure)",
             NumericKey{true, Interval{0.0, 1000000.0},
                        [](const Scene& s) -> std::optional<double> {
                            return double(s.exposure.first);
                        },
                        [](Scene& s, double v) { s.exposure.first = int(v); return true; }}},
            {"exposure.last", "integer", "the series' last",
             "≥ `exposure.first`; both must name time-steps of the series (checked when the scene meets it)",
             NumericKey{true, Interval{0.0, 1000000.0},
                        [](const Scene& s) -> std::optional<double> {
                            return s.exposure.last ? std::optional<double>(*s.exposure.last) : std::nullopt;
                        },
                        [](Scene& s, double v) { s.exposure.last = int(v); return true; }}},
            {"annotations", "object", "none",
             "the legend, title, caption, box and scale bar drawn onto the image: docs/annotations.md",
             std::nullopt},
            {"annotations.font_size", "number", "`13`", "text height in pixels on a 512-pixel-high image",
             NumericKey{false, Interval{4.0, 200.0},
                        [](const Scene& s) -> std::optional<double> { return s.annotations.fontSize; },
                        [](Scene& s, double v) { s.annotations.fontSize = v; return true; }}},
            {"animation", "object", "none",
             "keyframed tracks for `tstyles animate`: docs/animation.md",
             std::nullopt},
            {"probes", "list of 3-number lists", "none",
             "at most 8 places pinned in the window's probe panel, in the file's coordinates as `tstyles info` "
             "lists them; the window plots their values over time, `render` ignores them: docs/probe.md",
             std::nullopt},
        };
        const auto afterName = std::find_if(table.begin(), table.end(), [](const SceneKey& key) {
            return key.path == "compositor.name";
        }) + 1;
        const std::vector<SceneKey> options = compositorOptionKeys();
        table.insert(afterName, options.begin(), options.end());
        const auto afterCompositor = std::find_if(table.begin(), table.end(), [](const SceneKey& key) {
            return key.path == "compositor.reads";
        }) + 1;
        const std::vector<SceneKey> ray = rayModeKeys();
        table.insert(afterCompositor, ray.begin(), ray.end());
        return table;
    }();
    return keys;
}

}  // namespace

std::span<const SceneKey> sceneKeys() { return keyTable(); }

const SceneKey& sceneKey(std::string_view path) {
    const SceneKey* key = findSceneKey(path);
    if (!key) throw std::logic_error("no scene key \"" + std::string(path) + "\" in the key table");
    return *key;
}

const SceneKey* findSceneKey(std::string_view path) {
    const auto& keys = keyTable();
    const auto found = std::find_if(keys.begin(), keys.end(), [&](const SceneKey& key) { return key.path == path; });
    return found != keys.end() ? &*found : nullptr;
}

const NumericKey* numericSceneKey(std::string_view path) {
    const SceneKey* key = findSceneKey(path);
    return key && key->numeric ? &*key->numeric : nullptr;
}

double readKeyNumber(const JsonField& field) {
    const NumericKey* key = numericSceneKey(field.path());
    if (!key) throw std::logic_error("no numeric scene key \"" + field.path() + "\" in the key table");
    if (key->whole) return field.integerIn(int(key->range.low), int(key->range.high));
    return field.numberIn(key->range);
}

std::string allowedText(const SceneKey& key) {
    if (!key.numeric) return std::string(key.allowed);
    const std::string range = key.numeric->range.describe();
    return key.allowed.empty() ? range : range + "; " + std::string(key.allowed);
}

std::string sceneKeyTable() {
    std::string table = "| Key | Type | Default | Allowed |\n|---|---|---|---|\n";
    for (const SceneKey& key : keyTable()) {
        table += "| `" + std::string(key.path) + "` | " + std::string(key.type) + " | " + std::string(key.defaultText) +
                 " | " + allowedText(key) + " |\n";
    }
    return table;
}

}  // namespace tstyles
