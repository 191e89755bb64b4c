// A colour node's style is a built-in name ("glossy-blue") or the path of an image file.
#pragma once

#include <string>

namespace tstyles {

// True when `style` names an image file (it has a folder or an extension), not a built-in style.
bool isStyleFile(const std::string& style);

}  // namespace tstyles
