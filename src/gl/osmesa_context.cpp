// Headless OpenGL through Mesa's OSMesa, the fallback when EGL gives no context.
#include <GL/osmesa.h>

#include <vector>

#include "tstyles/core/errors.h"
#include "tstyles/gl/gl_loader.h"
#include "tstyles/gl/headless_context.h"

namespace tstyles {
namespace {

class OsMesaContext final : public HeadlessContext {
public:
    explicit OsMesaContext(bool debugOutput) {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (context_ == nullptr) throw GlUnavailableError("OSMesa: no OpenGL 4.5 core context");
        // OSMesa needs a colour buffer to make a context current; we render into framebuffer
        // objects, so a tiny one does.
        if (!OSMesaMakeCurrent(context_, surface_.data(), GL_UNSIGNED_BYTE, kSurfaceSize,
                               kSurfaceSize)) {
            OSMesaDestroyContext(context_);
            throw GlUnavailableError("OSMesa: cannot make the context current");
        }
        try {
            loadGlFunctions([](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); });
            if (currentGlVersion() < 45)
                throw GlUnavailableError("OSMesa: the context is only OpenGL " + currentGlRenderer());
            if (debugOutput) installGlDebugOutput();
        } catch (...) {
            OSMesaDestroyContext(context_);
            throw;
        }
    }
    ~OsMesaContext() override { OSMesaDestroyContext(context_); }

    std::string description() const override { return "OSMesa: " + currentGlRenderer(); }
    GlBackend backend() const override { return GlBackend::OsMesa; }

private:
    static constexpr int kSurfaceSize = 4;
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> surface_ = std::vector<unsigned char>(kSurfaceSize * kSurfaceSize * 4);
};

}  // namespace

std::unique_ptr<HeadlessContext> createOsMesaContext(bool debugOutput) {
    return std::make_unique<OsMesaContext>(debugOutput);
}

}  // namespace tstyles
