// The driver's limits on a frame's size, asked once per size change.
#include "render_size_limits.h"

#include <algorithm>
#include <string>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/gl/objects.h"

namespace tstyles {
namespace {

// GL_NVX_gpu_memory_info: total dedicated memory in KiB (NVIDIA); 0 where not reported.
constexpr GLenum kGpuMemoryTotalNvx = 0x9048;

GLint integer(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

std::string sizeText(glm::ivec2 size) { return std::to_string(size.x) + " x " + std::to_string(size.y); }

// The memory a frame's buffers may take: the GPU's where the driver says, else host memory.
double frameMemoryLimit() {
    if (hasGlExtension("GL_NVX_gpu_memory_info")) {
        const GLint kib = integer(kGpuMemoryTotalNvx);
        if (kib > 0) return double(kib) * 1024.0;
    }
    return double(defaultMemoryCap());
}

}  // namespace

void requireRenderableSize(glm::ivec2 size, int layers) {
    GLint viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    struct Limit {
        const char* name;
        GLint value;
    };
    const Limit limits[] = {{"GL_MAX_TEXTURE_SIZE", integer(GL_MAX_TEXTURE_SIZE)},
                            {"GL_MAX_RENDERBUFFER_SIZE", integer(GL_MAX_RENDERBUFFER_SIZE)},
                            {"GL_MAX_FRAMEBUFFER_WIDTH", integer(GL_MAX_FRAMEBUFFER_WIDTH)},
                            {"GL_MAX_FRAMEBUFFER_HEIGHT", integer(GL_MAX_FRAMEBUFFER_HEIGHT)},
                            {"GL_MAX_VIEWPORT_DIMS", std::min(viewport[0], viewport[1])}};
    for (const Limit& limit : limits)
        if (limit.value > 0 && std::max(size.x, size.y) > limit.value)
            throwInputError("", "image size",
                            sizeText(size) + " is larger than this OpenGL driver can render (" + limit.name + " " +
                                std::to_string(limit.value) + "): render at most " + std::to_string(limit.value) +
                                " pixels wide and high");
    const GLint maxLayers = integer(GL_MAX_ARRAY_TEXTURE_LAYERS);
    if (maxLayers > 0 && layers > maxLayers)
        throwInputError("", "time-steps",
                        std::to_string(layers) + " proxy layers are more than this OpenGL driver allows "
                        "(GL_MAX_ARRAY_TEXTURE_LAYERS " + std::to_string(maxLayers) + ")");
    // RGBA32F target (16 bytes), entry/exit depths (RG32F, 8 bytes a layer), and two host copies
    // of the read-back (16 bytes each) while the image is flipped.
    const double pixels = double(size.x) * double(size.y);
    const double bytes = pixels * (16.0 + 8.0 * double(std::max(layers, 1)) + 32.0);
    const double limit = frameMemoryLimit();
    if (bytes > limit)
        throwInputError("", "image size",
                        sizeText(size) + " with " + std::to_string(layers) + " entry/exit layers needs " +
                            byteCountText(bytes) + " of buffers, more than the " + byteCountText(limit) +
                            " available to the renderer: render a smaller image");
}

bool hasGlExtension(const char* wanted) {
    const GLint count = integer(GL_NUM_EXTENSIONS);
    for (GLint index = 0; index < count; ++index) {
        const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(index)));
        if (name != nullptr && std::string(name) == wanted) return true;
    }
    return false;
}

void requireAllocated(glm::ivec2 size, const char* what) {
    bool outOfMemory = false;
    for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError())
        outOfMemory = outOfMemory || error == GL_OUT_OF_MEMORY;
    if (outOfMemory)
        throwInputError("", "image size",
                        sizeText(size) + ": the OpenGL driver could not allocate the " + what +
                            " (GL_OUT_OF_MEMORY): render a smaller image");
}

}  // namespace tstyles
