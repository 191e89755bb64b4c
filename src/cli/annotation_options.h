// --legend, --annotate and --title: the scene's annotations switched on from the command line
// (render, animate).
#pragma once

#include <optional>
#include <string>

#include "cli11_forward.h"

#include "tstyles/scene/scene.h"

namespace tstyles::cli {

struct AnnotationOptions {
    bool legend = false;
    bool annotate = false;
    std::optional<std::string> title;
};
void addAnnotationOptions(CLI::App& command, AnnotationOptions& options);
void applyAnnotationOptions(Scene& scene, const AnnotationOptions& options);

}  // namespace tstyles::cli
