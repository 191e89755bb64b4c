// Telling built-in style names from style image paths.
#include "tstyles/scene/style_reference.h"

#include <filesystem>

namespace tstyles {

bool isStyleFile(const std::string& style) {
    const std::filesystem::path path(style);
    return path.has_extension() || path.has_parent_path();
}

}  // namespace tstyles
