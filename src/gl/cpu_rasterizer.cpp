#include "tstyles/gl/cpu_rasterizer.h"

namespace tstyles {

std::optional<std::string_view> cpuRasterizerName(std::string_view glRenderer) {
    for (std::string_view name : {std::string_view("llvmpipe"), std::string_view("softpipe")})
        if (glRenderer.find(name) != std::string_view::npos) return name;
    return std::nullopt;
}

bool isCpuRasterizer(std::string_view glRenderer) { return cpuRasterizerName(glRenderer).has_value(); }

}  // namespace tstyles
