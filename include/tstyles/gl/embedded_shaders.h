// The shaders/ folder compiled into the binary (generated at build time by tools/cmake/EmbedShaders.cmake).
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace tstyles {

const std::map<std::string, std::string_view>& embeddedShaderFiles();

}  // namespace tstyles
