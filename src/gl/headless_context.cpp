// Backend choice for headless rendering, and the KHR_debug hook shared by every context.
#include "tstyles/gl/headless_context.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "tstyles/core/errors.h"
#include "tstyles/gl/gl_api.h"

namespace tstyles {

std::string toString(GlBackend backend) {
    switch (backend) {
        case GlBackend::Auto: return "auto";
        case GlBackend::Egl: return "egl";
        case GlBackend::OsMesa: return "osmesa";
    }
    return "?";
}

std::optional<GlBackend> glBackendFromString(const std::string& name) {
    if (name == "auto") return GlBackend::Auto;
    if (name == "egl") return GlBackend::Egl;
    if (name == "osmesa") return GlBackend::OsMesa;
    return std::nullopt;
}

std::unique_ptr<HeadlessContext> createHeadlessContext(GlBackend backend, bool debugOutput) {
    std::string failures;
    if (backend == GlBackend::Auto || backend == GlBackend::Egl) {
        try {
            return createEglContext(debugOutput);
        } catch (const GlUnavailableError& error) {
            failures += std::string("\n  ") + error.what();
        }
    }
    if (backend == GlBackend::Auto || backend == GlBackend::OsMesa) {
        try {
            return createOsMesaContext(debugOutput);
        } catch (const GlUnavailableError& error) {
            failures += std::string("\n  ") + error.what();
        }
    }
    throw GlUnavailableError("no usable OpenGL 4.5 core context (backend " + toString(backend) +
                             "); tried:" + failures);
}

namespace {
void APIENTRY reportGlMessage(GLenum /*source*/, GLenum type, GLuint /*id*/, GLenum severity,
                                GLsizei /*length*/, const GLchar* message, const void* /*user*/) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    std::fprintf(stderr, "GL %s: %s\n", type == GL_DEBUG_TYPE_ERROR ? "error" : "message", message);
#ifndef NDEBUG
    if (type == GL_DEBUG_TYPE_ERROR) std::abort();
#endif
}
}  // namespace

void installGlDebugOutput() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(reportGlMessage, nullptr);
}

bool glDebugOutputRequested() {
#ifndef NDEBUG
    return true;
#else
    const char* value = std::getenv("TSTYLES_GL_DEBUG");
    return value != nullptr && std::strcmp(value, "1") == 0;
#endif
}

}  // namespace tstyles
