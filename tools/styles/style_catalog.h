// The built-in lit-sphere styles, by name (docs/styles.md shows each one).
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "shading.h"

namespace styles {

// A style is a function of the view-space normal (n.z >= 0) to a colour and an opacity factor.
struct StyleDefinition {
    std::string name;         // also the file name, <name>.png
    std::string description;  // one line for styles.json and the docs
    std::function<Rgba(const glm::dvec3& normal)> shade;
};

// Every built-in style, in the order styles.json lists them.
std::vector<StyleDefinition> builtInStyles();

}  // namespace styles
