// The sandbox of a scene's own compositor (CustomCompositor), checked when the scene is read:
// the code reaches only its inputs, its own variables and GLSL's built-in math, and its loops are
// bounded by the series (docs/compositors.md). Private to src/scene.
#pragma once

#include <optional>
#include <string>

namespace tstyles {

struct SandboxViolation {
    int line;  // in the compositor's code, from 1
    std::string problem;
};

std::optional<SandboxViolation> findSandboxViolation(const std::string& code);

}  // namespace tstyles
