// Whether the OpenGL implementation rasterizes on the CPU (Mesa's llvmpipe or softpipe) rather than
// on a GPU: what pays differs (per-thread arrays are cheap there and slow on a GPU; several
// contexts at once only share the same cores; textures live in host memory).
#pragma once

#include <optional>
#include <string_view>

namespace tstyles {

// The CPU rasterizer that `glRenderer` (the GL_RENDERER string, or a text that holds it, e.g.
// "llvmpipe (LLVM 15.0.6, 256 bits)") names: "llvmpipe" or "softpipe"; none for a GPU.
std::optional<std::string_view> cpuRasterizerName(std::string_view glRenderer);

bool isCpuRasterizer(std::string_view glRenderer);

}  // namespace tstyles
