// A picture of every style side by side, for the docs: each sphere is cut out at the disc and laid
// over a checkerboard, so that its transparency shows. The renderer never reads it.
#pragma once

#include <vector>

#include "lit_sphere_raster.h"
#include "style_catalog.h"

namespace styles {

// Cells of cellSize x cellSize in rows of `columns`, in the order given, on an opaque background.
RgbaImage drawContactSheet(const std::vector<StyleDefinition>& styles, int cellSize, int columns);

}  // namespace styles
