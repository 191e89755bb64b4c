// Named colour maps: sequential maps are perceptually ordered (CIELAB lightness rises), the cyclic
// map joins its ends, and the nodes made from a map reproduce it on a curve.
#include <cmath>

#include <gtest/gtest.h>

#include "tstyles/scene/color_map.h"

namespace tstyles {
namespace {

// CIELAB L* of an sRGB colour (D65).
double lightness(const glm::dvec3& srgb) {
    auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
    const double y = 0.2126 * linear(srgb.r) + 0.7152 * linear(srgb.g) + 0.0722 * linear(srgb.b);
    const double f = y > 216.0 / 24389.0 ? std::cbrt(y) : (24389.0 / 27.0 * y + 16.0) / 116.0;
    return 116.0 * f - 16.0;
}

TEST(ColorMap, SequentialMapsRiseInLightness) {
    for (const ColorMap& map : colorMaps()) {
        if (map.kind != ColorMapKind::Sequential) continue;
        double previous = -1.0;
        for (int i = 0; i <= 64; ++i) {
            const double l = lightness(colorAt(map, i / 64.0));
            EXPECT_GT(l, previous) << map.name << " at " << i / 64.0;
            previous = l;
        }
    }
}

TEST(ColorMap, CyclicMapJoinsItsEnds) {
    const ColorMap seasons = *colorMapNamed("seasons");
    EXPECT_EQ(seasons.kind, ColorMapKind::Cyclic);
    EXPECT_EQ(colorAt(seasons, 0.0), colorAt(seasons, 1.0));
}

TEST(ColorMap, EndsAndMiddle) {
    const ColorMap temporal = *colorMapNamed("temporal");
    EXPECT_EQ(colorAt(temporal, 0.0), temporal.colors.front());
    EXPECT_EQ(colorAt(temporal, 1.0), temporal.colors.back());
    EXPECT_EQ(colorAt(temporal, 0.5), temporal.colors[2]);  // five control colours: white in the middle
    EXPECT_EQ(colorAt(temporal, -1.0), temporal.colors.front());
    EXPECT_FALSE(colorMapNamed("rainbow").has_value());
}

TEST(ColorMap, NodesFromAMapGiveEachTimeStepItsColour) {
    const ColorMap temporal = *colorMapNamed("temporal");
    TransferFunction1D curve;
    curve.color = colorNodesFromMap(temporal, 0.0, 4.0, true, "matte-white");
    ASSERT_EQ(curve.color.size(), 5u);
    for (int step = 0; step <= 4; ++step) {
        EXPECT_EQ(curve.evaluate(step).color, colorAt(temporal, step / 4.0));
        EXPECT_EQ(curve.color[std::size_t(step)].style, "matte-white");
    }
    EXPECT_EQ(colorNodesFromMap(temporal, 0.0, 1.0, false).size(), 9u);
}

}  // namespace
}  // namespace tstyles
