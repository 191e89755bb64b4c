#include "tstyles/gl/cpu_rasterizer.h"

namespace tstyles {

bool isCpuRasterizer(std::string_view glRenderer) {
    return glRenderer.find("llvmpipe") != std::string_view::npos || glRenderer.find("softpipe") != std::string_view::npos;
}

}  // namespace tstyles
