// Headless OpenGL through EGL: Mesa's surfaceless platform, or the first EGL device (NVIDIA).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <mutex>
#include <vector>

#include "tstyles/core/errors.h"
#include "tstyles/gl/gl_api.h"
#include "tstyles/gl/headless_context.h"

namespace tstyles {
namespace {

std::string eglErrorName(EGLint error) {
    switch (error) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: return "EGL error " + std::to_string(error);
    }
}

[[noreturn]] void failEgl(const std::string& what) {
    throw GlUnavailableError("EGL: " + what + " (" + eglErrorName(eglGetError()) + ")");
}

bool hasExtension(const char* extensions, const std::string& name) {
    if (extensions == nullptr) return false;
    const std::string all = std::string(" ") + extensions + " ";
    return all.find(" " + name + " ") != std::string::npos;
}

struct OpenedDisplay {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string platform;
};

OpenedDisplay openDisplay() {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    std::string tried;
    if (getPlatformDisplay != nullptr && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return {display, "EGL surfaceless"};
        tried += std::string(tried.empty() ? "" : "; ") + "surfaceless platform failed (" + eglErrorName(eglGetError()) + ")";
    }
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (getPlatformDisplay != nullptr && queryDevices != nullptr) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (queryDevices(16, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr))
                    return {display, "EGL device " + std::to_string(i)};
            }
        }
        tried += std::string(tried.empty() ? "" : "; ") + "no usable EGL device among " + std::to_string(count);
    }
    throw GlUnavailableError("EGL: no headless display: " + (tried.empty() ? std::string("no platform extensions") : tried));
}

// EGL hands every caller of eglGetPlatformDisplay with the same arguments the same display, and
// one eglTerminate ends it for all; contexts on several threads (`tstyles check --jobs`) therefore
// share one display, initialised by the first and terminated by the last.
class SharedDisplay {
public:
    static OpenedDisplay acquire() {
        const std::lock_guard lock(mutex_);
        if (users_ == 0) opened_ = openDisplay();
        ++users_;
        return opened_;
    }
    static void release() {
        const std::lock_guard lock(mutex_);
        if (--users_ == 0) eglTerminate(opened_.display);
    }

private:
    static inline std::mutex mutex_;
    static inline int users_ = 0;
    static inline OpenedDisplay opened_;
};

class EglContext final : public HeadlessContext {
public:
    explicit EglContext(bool debugOutput) {
        auto opened = SharedDisplay::acquire();
        display_ = opened.display;
        platform_ = opened.platform;
        try {
            create(debugOutput);
        } catch (...) {
            release();
            throw;
        }
    }
    ~EglContext() override { release(); }

    std::string description() const override { return platform_ + ": " + currentGlRenderer(); }
    GlBackend backend() const override { return GlBackend::Egl; }

private:
    void create(bool debugOutput) {
        if (!eglBindAPI(EGL_OPENGL_API)) failEgl("desktop OpenGL is not supported");
        EGLConfig config = nullptr;
        if (!hasExtension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
            const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                               EGL_OPENGL_BIT, EGL_NONE};
            EGLint count = 0;
            if (!eglChooseConfig(display_, configAttributes, &config, 1, &count) || count < 1)
                failEgl("no config for desktop OpenGL");
        }
        std::vector<EGLint> attributes = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                          EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                          EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
        if (debugOutput) attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
        attributes.push_back(EGL_NONE);
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes.data());
        if (context_ == EGL_NO_CONTEXT) failEgl("no OpenGL 4.5 core context");
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            failEgl("cannot make the context current without a surface");
        loadGlFunctions([](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); });
        if (currentGlVersion() < 45)
            throw GlUnavailableError("EGL: the context is only OpenGL " + currentGlRenderer());
        if (debugOutput) installGlDebugOutput();
    }

    void release() {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        SharedDisplay::release();
        display_ = EGL_NO_DISPLAY;
        context_ = EGL_NO_CONTEXT;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    std::string platform_;
};

}  // namespace

std::unique_ptr<HeadlessContext> createEglContext(bool debugOutput) {
    return std::make_unique<EglContext>(debugOutput);
}

}  // namespace tstyles
