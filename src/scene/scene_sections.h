// The scene file's sections that live in their own files (animation, annotations, compositor, ray),
// shared by the reader and the writer. Private to src/scene.
#pragma once

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "tstyles/core/json_field.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

// `scene` is what was read of the file before: each key is checked against it.
Animation readAnimation(const JsonField& section, const Scene& scene, const std::filesystem::path& origin);
nlohmann::ordered_json animationJson(const Animation& animation);

// "compositor": sets scene.compositor and scene.compositorOptions.
void readCompositor(const JsonField& section, const std::filesystem::path& origin, Scene& scene);
nlohmann::ordered_json compositorJson(const Scene& scene, const std::filesystem::path& sceneFolder);

// "ray": sets scene.rayMode and scene.rayOptions; written only where the mode is not composite.
void readRay(const JsonField& section, Scene& scene);
std::optional<nlohmann::ordered_json> rayJson(const Scene& scene);

Annotations readAnnotations(const JsonField& section);
nlohmann::ordered_json annotationsJson(const Annotations& annotations);

}  // namespace tstyles
