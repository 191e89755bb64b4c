// Loading GL entry points, without pulling in GL headers: for code that must include a system
// header of its own (GL/osmesa.h includes GL/gl.h, which clashes with glcorearb.h).
#pragma once

#include <string>

namespace tstyles {

using GlProcLoader = void* (*)(const char* name);

// Resolves every entry point in gl_functions.inc through `loader`. Throws GlUnavailableError naming
// the first function that the implementation does not provide.
void loadGlFunctions(GlProcLoader loader);

// The GL version of the current context, e.g. 45 for 4.5.
int currentGlVersion();
std::string currentGlRenderer();

}  // namespace tstyles
