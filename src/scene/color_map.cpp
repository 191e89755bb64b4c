// The named colour maps (color_map.h). Control colours of the published maps are their values at
// evenly spaced points, to about two digits (viridis and magma: van der Walt and Smith's matplotlib
// maps; cividis: Nuñez, Anderton and Renslow 2018); the rest are drawn here for their purpose, the
// sequential ones with a lightness that rises (tests/model/color_map_test.cpp).
#include "tstyles/scene/color_map.h"

#include <algorithm>
#include <cmath>

namespace tstyles {

const std::vector<ColorMap>& colorMaps() {
    static const std::vector<ColorMap> maps = {
        {"temporal", ColorMapKind::Diverging, "time: blue, through white, to orange (the paper's scale)",
         {{0.13, 0.29, 0.75}, {0.45, 0.60, 0.90}, {0.95, 0.95, 0.95}, {0.97, 0.70, 0.40}, {0.90, 0.45, 0.05}}},
        {"viridis", ColorMapKind::Sequential, "perceptually ordered, dark blue to yellow",
         {{0.267, 0.005, 0.329}, {0.283, 0.141, 0.458}, {0.254, 0.265, 0.530}, {0.207, 0.372, 0.553},
          {0.164, 0.471, 0.558}, {0.128, 0.567, 0.551}, {0.135, 0.659, 0.518}, {0.267, 0.749, 0.441},
          {0.478, 0.821, 0.318}, {0.741, 0.873, 0.150}, {0.993, 0.906, 0.144}}},
        {"magma", ColorMapKind::Sequential, "perceptually ordered, black through purple to light yellow",
         {{0.001, 0.000, 0.014}, {0.078, 0.054, 0.211}, {0.232, 0.060, 0.437}, {0.390, 0.100, 0.502},
          {0.550, 0.161, 0.506}, {0.716, 0.215, 0.475}, {0.868, 0.288, 0.409}, {0.967, 0.440, 0.360},
          {0.994, 0.624, 0.427}, {0.995, 0.812, 0.572}, {0.987, 0.991, 0.750}}},
        {"cividis", ColorMapKind::Sequential, "perceptually ordered and readable with colour-vision deficiency",
         {{0.000, 0.135, 0.304}, {0.092, 0.211, 0.429}, {0.259, 0.290, 0.424}, {0.365, 0.369, 0.430},
          {0.455, 0.449, 0.457}, {0.550, 0.531, 0.472}, {0.650, 0.616, 0.468}, {0.753, 0.705, 0.442},
          {0.860, 0.797, 0.391}, {0.969, 0.894, 0.318}, {0.995, 0.907, 0.143}}},
        {"green-orange", ColorMapKind::Sequential, "change: green to orange (the paper's gradient TSTF)",
         {{0.10, 0.45, 0.15}, {0.55, 0.65, 0.15}, {0.98, 0.60, 0.15}}},
        {"blue-red", ColorMapKind::Diverging, "signed values: blue below, white in the middle, red above",
         {{0.23, 0.30, 0.75}, {0.55, 0.69, 0.99}, {0.87, 0.87, 0.87}, {0.96, 0.60, 0.48}, {0.71, 0.02, 0.15}}},
        {"seasons", ColorMapKind::Cyclic, "cyclic, for seasons: winter blue, spring green, summer yellow, autumn red",
         {{0.25, 0.40, 0.85}, {0.25, 0.70, 0.40}, {0.90, 0.80, 0.20}, {0.85, 0.35, 0.20}, {0.25, 0.40, 0.85}}},
    };
    return maps;
}

std::optional<ColorMap> colorMapNamed(const std::string& name) {
    for (const ColorMap& map : colorMaps())
        if (map.name == name) return map;
    return std::nullopt;
}

glm::dvec3 colorAt(const ColorMap& map, double t) {
    const double position = std::clamp(t, 0.0, 1.0) * double(map.colors.size() - 1);
    const std::size_t below = std::min(std::size_t(position), map.colors.size() - 2);
    return glm::mix(map.colors[below], map.colors[below + 1], position - double(below));
}

std::vector<ColorNode> colorNodesFromMap(const ColorMap& map, double low, double high, bool wholeSteps,
                                         const std::string& style) {
    constexpr int kEvenNodes = 9;
    constexpr int kMostStepNodes = 33;
    const int steps = int(std::llround(high - low)) + 1;
    const int count = wholeSteps && steps <= kMostStepNodes ? steps : kEvenNodes;
    std::vector<ColorNode> nodes;
    for (int i = 0; i < count; ++i) {
        const double t = count == 1 ? 0.5 : double(i) / double(count - 1);
        ColorNode node;
        node.at = low + t * (high - low);
        node.color = colorAt(map, t);
        node.style = style;
        nodes.push_back(node);
    }
    return nodes;
}

}  // namespace tstyles
