// Named colour maps for transfer functions: the paper's time scale (blue, through white, to orange),
// published sequential maps, a diverging and a cyclic one. A map is a list of control colours,
// evenly spaced over [0, 1] and interpolated linearly in sRGB between them; the automatic scene
// colours time with them and the viewer's curve editors apply one with a click. GL-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/scene/transfer_function.h"

namespace tstyles {

enum class ColorMapKind { Sequential, Diverging, Cyclic };

struct ColorMap {
    std::string name;
    ColorMapKind kind;
    std::string purpose;              // one line for menus and docs
    std::vector<glm::dvec3> colors;   // control colours at 0, 1/(k-1), ..., 1
};

const std::vector<ColorMap>& colorMaps();
std::optional<ColorMap> colorMapNamed(const std::string& name);
// The map's colour at t in [0, 1] (clamped).
glm::dvec3 colorAt(const ColorMap& map, double t);

// Colour nodes that make a curve over [low, high] look like the map: one per whole position when
// `wholeSteps` (time-steps of the index TSTF, at most 33), else 9 evenly spaced. Each node keeps
// `style` (a lit-sphere style the map tints; empty for flat colours).
std::vector<ColorNode> colorNodesFromMap(const ColorMap& map, double low, double high, bool wholeSteps,
                                         const std::string& style = "");

}  // namespace tstyles
