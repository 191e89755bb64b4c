// Run-time loading of the GL entry points listed in gl_functions.inc.
#include "tstyles/gl/gl_api.h"

#include <mutex>

#include "tstyles/core/errors.h"

namespace tstyles::gl_api {

#define TSTYLES_GL_FUNCTION(type, name) type name = nullptr;
#include "tstyles/gl/gl_functions.inc"
#undef TSTYLES_GL_FUNCTION

}  // namespace tstyles::gl_api

namespace tstyles {

// Contexts made on several threads at once (`tstyles check --jobs`) load the same entry points
// while other threads already call them: EGL and OSMesa return context-independent addresses, so
// a pointer is only written when it changes (the first context, or a switch of backend), and
// threads that load the same values only read. The mutex keeps two first loads from racing.
void loadGlFunctions(GlProcLoader loader) {
    static std::mutex loading;
    const std::lock_guard lock(loading);
#define TSTYLES_GL_FUNCTION(type, name)                                                       \
    if (auto loaded = reinterpret_cast<type>(loader(#name)); loaded != gl_api::name)          \
        gl_api::name = loaded;                                                                \
    if (gl_api::name == nullptr)                                                              \
        throw GlUnavailableError("the OpenGL implementation does not provide " #name);
#include "tstyles/gl/gl_functions.inc"
#undef TSTYLES_GL_FUNCTION
}

int currentGlVersion() {
    GLint major = 0;
    GLint minor = 0;
    gl_api::glGetIntegerv(GL_MAJOR_VERSION, &major);
    gl_api::glGetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 10 + minor;
}

std::string currentGlRenderer() {
    const auto* renderer = reinterpret_cast<const char*>(gl_api::glGetString(GL_RENDERER));
    const auto* version = reinterpret_cast<const char*>(gl_api::glGetString(GL_VERSION));
    return std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
}

}  // namespace tstyles
