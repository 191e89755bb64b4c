// The interactive viewer's entry point, as `tstyles view` calls it.
#pragma once

#include <filesystem>
#include <optional>

#include <glm/glm.hpp>

namespace tstyles::viewer {

struct ViewerOptions {
    // A scene file or a dataset (folder or manifest); none: the bundled default.
    std::optional<std::filesystem::path> input;
    std::filesystem::path dataDirectory;  // where the bundled default is looked for
    std::optional<std::filesystem::path> script;
    glm::ivec2 windowSize{1280, 800};
    std::optional<std::filesystem::path> shaderDirectory;
    bool vsync = true;
};

// Opens the window and runs until it is closed or a script quits. Returns the exit code (0).
// Throws InputError for a bad input or script and GlUnavailableError when no window with OpenGL
// 4.5 can be opened.
int runViewer(const ViewerOptions& options);

}  // namespace tstyles::viewer
