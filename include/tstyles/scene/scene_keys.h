// The scene file's keys, described once: each line names a key by its path (as error messages and
// animation tracks name it), its type, its default and what it takes. The reader checks numbers
// against their line's range, an animated value is rounded where the line says whole and applied to
// the scene through the line's accessors, the viewer's widgets take their ranges and tooltips from
// it, and docs/scene-format.md's table of keys is generated from it (tools/write_doc_tables.cpp;
// a test fails when the committed table differs).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "tstyles/core/json_field.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

// A key that holds one number at a fixed path: what it takes, and where it is in a Scene.
struct NumericKey {
    bool whole = false;  // an integer: an animated value is rounded
    Interval range;      // the values the reader takes
    // The key's value in `scene`, or none where the scene has no number there (the camera is a
    // look_at, the compositor takes no threshold, the value is "auto" or left to the data).
    std::function<std::optional<double>(const Scene& scene)> get;
    // Sets a value inside `range`; false where the scene has no place for it (a look_at camera, a
    // compositor without a threshold, a value that is "auto"), as a scene file would refuse it.
    // A key that is only absent (no step, no last time-step) is set.
    std::function<bool(Scene& scene, double value)> set;
};

// A compositor's options ("compositor.threshold") are lines made from the table of compositors
// (temporal_compositors.h), and so are the lists of compositors in the lines of "compositor".
struct SceneKey {
    std::string path;         // "raycast.termination"
    std::string type;         // as the documentation says it: "number", "3 numbers", "string or object"
    std::string defaultText;  // markdown: "`0.99`", "half the finest voxel spacing"
    // What the key takes, in markdown; for a numeric key, after its range ("(0, 1]; rays stop ...").
    std::string allowed;
    std::optional<NumericKey> numeric;
};

// Every key of the scene file, in the order docs/scene-format.md lists them.
std::span<const SceneKey> sceneKeys();
// The line of a key path; std::logic_error for a path the table lacks (a programming error).
const SceneKey& sceneKey(std::string_view path);
// The line of a key path, or null for a path the table lacks (a node's "at", a background channel).
const SceneKey* findSceneKey(std::string_view path);
// The numeric key at `path` ("image.width"), or null for any other path (a node's "at", a string).
const NumericKey* numericSceneKey(std::string_view path);

// The number of the numeric key that `field` is (its path is the key's: "raycast.termination"),
// checked against the key's range (a whole one as an integer); std::logic_error for another path.
double readKeyNumber(const JsonField& field);

// The "Allowed" column of a key: a numeric key's range, then the line's text.
std::string allowedText(const SceneKey& key);
// The markdown table of docs/scene-format.md's "Keys" section, generated from sceneKeys(); it stands
// between these two lines there.
std::string sceneKeyTable();
inline constexpr const char* kSceneKeyTableBegin =
    "<!-- The table of keys is generated from src/scene/scene_keys.cpp: build/tools/write_doc_tables docs -->";
inline constexpr const char* kSceneKeyTableEnd = "<!-- End of the generated table of keys. -->";

}  // namespace tstyles
