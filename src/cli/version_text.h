// What `tstyles --version` prints: the version, the OpenGL renderer `render` would use, the data folder.
#pragma once

#include <string>

namespace tstyles::cli {

// Tries a headless context as `render --backend auto` does; without one it says why instead of failing.
std::string versionText();

}  // namespace tstyles::cli
