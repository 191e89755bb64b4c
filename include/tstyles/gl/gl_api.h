// OpenGL 4.5 core entry points, loaded at run time from whichever headless or windowed context is
// current (EGL, OSMesa, GLFW). Include this instead of any system GL header.
//
// The pointers are process-wide, as the GL entry points themselves are: they are written once by
// loadGlFunctions() right after the first context is made current, and read-only afterwards.
#pragma once

#include <GL/glcorearb.h>

#include "tstyles/gl/gl_loader.h"

namespace tstyles::gl_api {

#define TSTYLES_GL_FUNCTION(type, name) extern type name;
#include "tstyles/gl/gl_functions.inc"
#undef TSTYLES_GL_FUNCTION

}  // namespace tstyles::gl_api


// Plain GL names for the loaded pointers, as GL code is usually written.
#define TSTYLES_GL_FUNCTION(type, name) using ::tstyles::gl_api::name;
#include "tstyles/gl/gl_functions.inc"
#undef TSTYLES_GL_FUNCTION
