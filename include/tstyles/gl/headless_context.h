// An OpenGL 4.5 core context without a window: EGL surfaceless (or an EGL device) first, OSMesa
// second. Creating one makes it current on the calling thread and loads the GL entry points.
// Several threads may each create and use their own context of one backend at once (`tstyles
// check --jobs`); a context stays current on the thread that created it until it is destroyed there.
#pragma once

#include <memory>
#include <optional>
#include <string>

namespace tstyles {

enum class GlBackend { Auto, Egl, OsMesa };

std::string toString(GlBackend backend);
std::optional<GlBackend> glBackendFromString(const std::string& name);

class HeadlessContext {
public:
    virtual ~HeadlessContext() = default;
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    // Which backend and renderer this is, e.g. "EGL surfaceless: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5".
    virtual std::string description() const = 0;
    // Egl or OsMesa (never Auto): the backend that further contexts of this process must use, as
    // the GL entry points are process-wide and differ between the two.
    virtual GlBackend backend() const = 0;

protected:
    HeadlessContext() = default;
};

// Tries the backends in order (Auto: EGL, then OSMesa). With `debugOutput` the context is a debug
// context and GL errors are reported through KHR_debug. Throws GlUnavailableError listing every
// backend tried and why it failed.
std::unique_ptr<HeadlessContext> createHeadlessContext(GlBackend backend, bool debugOutput);

// Backend-specific factories, used by createHeadlessContext. Each throws GlUnavailableError.
std::unique_ptr<HeadlessContext> createEglContext(bool debugOutput);
std::unique_ptr<HeadlessContext> createOsMesaContext(bool debugOutput);

// Installs the KHR_debug message callback on the current context (prints GL errors to stderr;
// in debug builds an error aborts, so a broken GL call is found where it happens).
void installGlDebugOutput();

// True when GL debug output is wanted: debug builds, or TSTYLES_GL_DEBUG=1 in the environment.
bool glDebugOutputRequested();

}  // namespace tstyles
