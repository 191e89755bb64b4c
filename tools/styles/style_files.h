// Writing the style library: one PNG per style and the styles.json index beside them.
#pragma once

#include <filesystem>
#include <vector>

#include "lit_sphere_raster.h"
#include "style_catalog.h"

namespace styles {

// 8-bit RGBA PNG with straight alpha, written through a temporary file. InputError naming the file
// on failure.
void writePng(const RgbaImage& image, const std::filesystem::path& file);

// {"styles": [{"name", "file", "description"}, ...]}, files relative to the index's folder.
void writeStyleIndex(const std::vector<StyleDefinition>& styles, const std::filesystem::path& file);

// The file name a style is written under.
std::string styleFileName(const StyleDefinition& style);

}  // namespace styles
