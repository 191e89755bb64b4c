// What a map shows (issue 51): the automatic scene of a monthly ocean climatology seen from above
// gives each place the time colour of the layer where it changes most. The file
// (testdata::writeOceanClimatology) has a surface warmest in August north of the equator and in
// February south of it, and layers below whose season comes a month later for every 40 m and
// shrinks; compositing every depth mixed their months (and the deep water's grey) into each
// column. The picture is read as the issue asks: the hue of the northern and southern bands.
#include <array>
#include <filesystem>
#include <iostream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "../data/realistic_datasets.h"
#include "render_test_support.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/camera.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 256;

struct Band {
    double share = 0.0;  // of the band's opaque pixels, those nearest to the expected month's colour
    int pixels = 0;
};

struct MapBands {
    Band north;  // 30 .. 60 N, expected August
    Band south;  // 30 .. 60 S, expected February
    Band equator;  // 4 S .. 4 N, expected no time colour: the STF's grey
};

// The index of the time colour (or -1 for a grey) nearest to a pixel's colour.
int nearestMonth(glm::vec3 colour, const Scene& scene, int months) {
    int nearest = -1;
    // A grey: the unchanged places (no hue). The temporal map's middle (June, July) is near white,
    // brighter than the unchanged share of the STF's white.
    const float spread = std::max({colour.r, colour.g, colour.b}) - std::min({colour.r, colour.g, colour.b});
    float best = spread < 0.02f ? 0.0f : 1e9f;
    if (spread >= 0.02f)
        for (int month = 0; month < months; ++month) {
            const glm::vec3 expected(scene.indexTstf.curve.evaluate(double(month)).color);
            const float distance = glm::length(colour - expected);
            if (distance < best) {
                best = distance;
                nearest = month;
            }
        }
    return nearest;
}

Band readBand(const Image& image, const Scene& scene, int months, int firstRow, int lastRow, int expected) {
    Band band;
    int matching = 0;
    for (int y = firstRow; y <= lastRow; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4 pixel = image.at(x, y);
            if (pixel.a < 0.2f) continue;  // land, and the space around the map
            ++band.pixels;
            if (nearestMonth(glm::vec3(pixel) / pixel.a, scene, months) == expected) ++matching;
        }
    band.share = band.pixels > 0 ? double(matching) / band.pixels : 0.0;
    return band;
}

MapBands renderClimatology(bool largestChange) {
    const auto folder = std::filesystem::temp_directory_path() / ("tstyles_map_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const auto file = folder / "woa-climatology.nc";
    testdata::writeOceanClimatology(file);
    Series raw = openSeries(file, ReadOptions{});
    std::filesystem::remove_all(folder);
    Scene scene = automaticScene(raw, file).scene;
    EXPECT_EQ(toString(scene.rayMode), "largest-change") << "the automatic scene of a map";
    if (!largestChange) applyAutomaticRay(scene, raw, automaticOpacityWindow(raw), kCompositeRay);
    scene.width = scene.height = kSize;
    scene.background = glm::dvec4(0.0);  // transparent: the map's pixels are those with alpha
    const int months = int(raw.size());
    const SceneOnSeries fitted = fitSceneToSeries(scene, std::move(raw));
    Renderer& renderer = testRenderer();
    renderer.setSeries(fitted.series);
    const Image image = renderImage(renderer, fitted.scene, fitted.framed, fitted.series.worldBounds());
    // A latitude's row at the surface (longitude 0, depth 0), through the view the image was drawn with.
    const View view = resolveView(fitted.scene.camera, fitted.framed, fitted.series.worldBounds(), kSize, kSize);
    auto rowOf = [&](double latitude) {
        const glm::dvec3 display = fitted.frame.toDisplay(glm::dvec3(0.0, latitude, 0.0));
        const glm::dvec4 clip = view.projectionMatrix * view.viewMatrix * glm::dvec4(display, 1.0);
        return int(std::lround((0.5 - 0.5 * clip.y / clip.w) * kSize));
    };
    MapBands bands;
    bands.north = readBand(image, fitted.scene, months, rowOf(60.0), rowOf(30.0), 7);
    bands.south = readBand(image, fitted.scene, months, rowOf(-30.0), rowOf(-60.0), 1);
    bands.equator = readBand(image, fitted.scene, months, rowOf(4.0), rowOf(-4.0), -1);
    std::cout << (largestChange ? "largest-change" : "composite") << ": north " << bands.north.share << " of "
              << bands.north.pixels << " August, south " << bands.south.share << " of " << bands.south.pixels
              << " February, equator " << bands.equator.share << " of " << bands.equator.pixels << " grey\n";
    return bands;
}

// Measured on llvmpipe (EGL and OSMesa): every opaque pixel of the bands as expected (north 1922 of
// 1922 August, south 3305 of 3305 February, equator 970 of 970 grey). Composited, as the scene was
// until now: north 0 August, south 0 February (the months of 50 to 100 m mixed in, and the deep
// water's grey). With the perspective camera the maps had, 0.88 of the north: the rays leaned
// under the coasts to the deep water (the map is now orthographic).
TEST(MapTimeColours, EachBandShowsTheMonthItsSurfacePeaksIn) {
    const MapBands bands = renderClimatology(true);
    EXPECT_GT(bands.north.pixels, 100);
    EXPECT_GT(bands.south.pixels, 100);
    EXPECT_GE(bands.north.share, 0.95);
    EXPECT_GE(bands.south.share, 0.95);
    EXPECT_GE(bands.equator.share, 0.95);
}

TEST(MapTimeColours, CompositingEveryDepthMixedTheMonths) {
    const MapBands bands = renderClimatology(false);
    EXPECT_LT(bands.north.share, 0.5);
    EXPECT_LT(bands.south.share, 0.5);
}

}  // namespace
}  // namespace tstyles::testing
