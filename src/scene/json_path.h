// Scene values named by the path that error messages use ("stf.opacity[2].at"): how animation
// tracks address any number of a scene file. Private to src/scene.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

namespace tstyles {

// One step of a path: an object member or an array element.
using JsonPathStep = std::variant<std::string, std::size_t>;

// The steps of "a.b[2].c"; none for text that is not such a path.
std::optional<std::vector<JsonPathStep>> parseJsonPath(const std::string& path);

// Sets the number at `steps` in `root`. Missing object members on the way are made (the scene
// reader then judges their names); a missing array element, or a step into a value of the wrong
// kind, gives false and leaves `root` as far as it got.
bool setNumberAtPath(nlohmann::json& root, const std::vector<JsonPathStep>& steps, double value);

}  // namespace tstyles
