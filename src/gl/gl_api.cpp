// Run-time loading of the GL entry points listed in gl_functions.inc.
#include "tstyles/gl/gl_api.h"

#include "tstyles/core/errors.h"

namespace tstyles::gl_api {

#define TSTYLES_GL_FUNCTION(type, name) type name = nullptr;
#include "tstyles/gl/gl_functions.inc"
#undef TSTYLES_GL_FUNCTION

}  // namespace tstyles::gl_api

namespace tstyles {

void loadGlFunctions(GlProcLoader loader) {
#define TSTYLES_GL_FUNCTION(type, name)                                                       \
    gl_api::name = reinterpret_cast<type>(loader(#name));                                     \
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
