// Options and lookups shared by the subcommands.
#include <cstdlib>

#include "commands.h"
#include "tstyles/core/errors.h"

namespace tstyles::cli {

void addGlOptions(CLI::App& command, GlOptions& options) {
    command.add_option("--backend", options.backend, "Headless OpenGL: auto (EGL, then OSMesa), egl, osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command.add_option("--shader-dir", options.shaderDirectory,
                       "Load shaders from this folder instead of the embedded copy (also: TSTYLES_SHADER_DIR)")
        ->check(CLI::ExistingDirectory);
}

GlBackend parseBackend(const std::string& name) {
    auto backend = glBackendFromString(name);
    if (!backend) throwInputError("", "--backend", "unknown backend \"" + name + "\"");
    return *backend;
}

}  // namespace tstyles::cli
