// Whether a path the user gives is a scene file or a dataset: `render`, `view` and `scene` accept
// either.
#pragma once

#include <filesystem>

namespace tstyles {

enum class InputKind { Scene, Dataset };

// A folder, a JSON file that is a series manifest, or a file that is not JSON (a reader's:
// docs/readers.md) is a dataset; a JSON file naming a dataset is a scene. A
// file that cannot be opened counts as a scene, so that the scene reader says what is wrong.
InputKind classifyInput(const std::filesystem::path& path);

}  // namespace tstyles
