// What the OpenGL driver can render into: an image size over its limits, or one whose buffers do
// not fit the memory there is, is an input problem (exit 2 naming the size and the limit), not a
// framebuffer that silently fails to be complete.
#pragma once

#include <glm/glm.hpp>

namespace tstyles {

// Checks `size` against GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE, GL_MAX_VIEWPORT_DIMS and
// GL_MAX_FRAMEBUFFER_WIDTH/HEIGHT, `layers` against GL_MAX_ARRAY_TEXTURE_LAYERS, and the bytes of
// the frame's buffers (RGBA32F target, RG32F entry/exit per layer, the read-back) against the GPU
// memory the driver reports, else the memory cap (llvmpipe and OSMesa render in host memory).
void requireRenderableSize(glm::ivec2 size, int layers);

// After allocating `what`: GL_OUT_OF_MEMORY becomes an InputError naming the image size.
void requireAllocated(glm::ivec2 size, const char* what);

// Whether the current context's driver lists the extension.
bool hasGlExtension(const char* wanted);

}  // namespace tstyles
