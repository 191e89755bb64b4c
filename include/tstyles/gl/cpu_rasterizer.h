// Whether the OpenGL implementation rasterizes on the CPU (Mesa's llvmpipe or softpipe) rather than
// on a GPU: what pays differs (per-thread arrays are cheap there and slow on a GPU; several
// contexts at once only share the same cores; textures live in host memory).
#pragma once

#include <string_view>

namespace tstyles {

// `glRenderer`: the GL_RENDERER string, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
bool isCpuRasterizer(std::string_view glRenderer);

}  // namespace tstyles
