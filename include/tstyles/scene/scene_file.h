// Scene files: JSON in, JSON out (format: docs/scene-format.md).
#pragma once

#include <filesystem>
#include <string>

#include "tstyles/scene/scene.h"

namespace tstyles {

// Parses a scene file. Unknown keys, wrong types and out-of-range values are InputErrors that name
// the file, the key (as a JSON path such as "stf.opacity[2].at") and the problem. A relative dataset
// path is resolved against the scene file's folder.
Scene loadScene(const std::filesystem::path& sceneFile);

// The same from text; `origin` is used in messages and to resolve a relative dataset path.
Scene parseScene(const std::string& json, const std::filesystem::path& origin);

// Writes the scene as JSON (dataset path relative to the scene's folder when possible), through a
// temporary file and a rename. saveScene followed by loadScene gives back an equal Scene.
void saveScene(const Scene& scene, const std::filesystem::path& sceneFile);
std::string sceneToJson(const Scene& scene, const std::filesystem::path& sceneFolder);

}  // namespace tstyles
