// Lit-sphere styles by reference: a built-in name (data/styles/<name>.png) or the path of any image
// OpenImageIO reads. Loaded images are checked (square, not empty) and kept for reuse.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tstyles/image/image.h"

namespace tstyles {

// The file behind a style reference.
std::filesystem::path resolveStyleFile(const std::string& style);

// The names of the built-in styles (the PNG files in the bundled data/styles/).
std::vector<std::string> builtInStyleNames();

class StyleLibrary {
public:
    // The style's image, loaded on first use. InputError naming the file for a missing,
    // unreadable, empty or non-square image, or an unknown built-in name (with the known ones).
    const Image& image(const std::string& style);

private:
    std::map<std::string, Image> loaded_;
};

}  // namespace tstyles
