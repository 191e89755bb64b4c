// `tstyles --version`: the project's version from CMake, the GL renderer, where the bundled data is.
#include "version_text.h"

#include "tstyles/core/bundled_data.h"
#include "tstyles/core/errors.h"
#include "tstyles/gl/headless_context.h"

namespace tstyles::cli {
namespace {

// The first line of the reasons: the full list (every backend tried) is what `render` prints.
std::string openGlLine() {
    try {
        return "OpenGL: " + createHeadlessContext(GlBackend::Auto, false)->description();
    } catch (const GlUnavailableError& error) {
        const std::string reason = error.what();
        return "OpenGL: none usable here, `render` would fail: " + reason.substr(0, reason.find('\n'));
    }
}

}  // namespace

std::string versionText() {
    return "tstyles " TSTYLES_VERSION "\n" + openGlLine() + "\nData: " + describe(bundledDataChoice());
}

}  // namespace tstyles::cli
