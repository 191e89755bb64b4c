// The automatic scene on files shaped like scientists' own (tests/data/realistic_datasets.h), read
// through the readers as `tstyles render FILE` reads them: the surface faces the camera with north
// up, air is transparent, each time-step of a moving blob has its own colour, and max density
// change differs from temporal MIP. Pixel-region checks, no golden images.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "../data/realistic_datasets.h"
#include "render_test_support.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 160;

std::filesystem::path sampleFolder() {
    static const auto folder = [] {
        // One folder per test process: ctest runs the EGL and OSMesa variants at the same time.
        auto path = std::filesystem::temp_directory_path() / ("tstyles_automatic_" + std::to_string(::getpid()));
        std::filesystem::create_directories(path);
        return path;
    }();
    return folder;
}

struct AutomaticRender {
    Scene scene;
    Image image;
};

AutomaticRender renderAutomatically(const std::filesystem::path& file,
                                    std::optional<TemporalCompositor> compositor = std::nullopt) {
    Series raw = openSeries(file, ReadOptions{});
    Scene scene = automaticScene(raw, file).scene;
    scene.width = scene.height = kSize;
    // Transparent, so that a pixel's alpha is the opacity the ray gathered.
    scene.background = glm::dvec4(0.0);
    if (compositor) scene.compositor = *compositor;
    const SceneOnSeries fitted = fitSceneToSeries(scene, std::move(raw));
    Renderer& renderer = testRenderer();
    renderer.setSeries(fitted.series);
    return {fitted.scene, renderImage(renderer, fitted.scene, fitted.framed, fitted.series.worldBounds())};
}

bool isBackground(const glm::vec4& pixel) { return pixel == glm::vec4(0.0f); }

// Centroid (column, row from the top) of the pixels whose colour is closest to `reference`
// among the candidates, and how many there are.
struct Region {
    glm::dvec2 centroid{0.0};
    int pixels = 0;
};

Region regionNearest(const Image& image, const glm::vec3& reference, const std::vector<glm::vec3>& candidates) {
    Region region;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4 pixel = image.at(x, y);
            if (pixel.a < 0.15f) continue;
            const glm::vec3 colour = glm::vec3(pixel) / pixel.a;
            const glm::vec3 hue = colour / std::max(1e-3f, std::max({colour.r, colour.g, colour.b}));
            float best = 1e9f;
            glm::vec3 nearest{};
            for (const glm::vec3& candidate : candidates)
                if (const float d = glm::distance(hue, candidate); d < best) {
                    best = d;
                    nearest = candidate;
                }
            if (nearest != reference) continue;
            region.centroid += glm::dvec2(x, y);
            ++region.pixels;
        }
    if (region.pixels > 0) region.centroid /= double(region.pixels);
    return region;
}

glm::vec3 normalisedHue(const glm::dvec3& colour) {
    return glm::vec3(colour / std::max({colour.r, colour.g, colour.b}));
}

TEST(AutomaticSceneRender, OceanSurfaceFacesTheCameraWithNorthUp) {
    const auto file = sampleFolder() / "ocean-anomalies.nc";
    testdata::writeOceanAnomalies(file);
    const AutomaticRender render = renderAutomatically(file);
    // Time-step 0 is a warm anomaly at the surface in the north-west, time-step 2 near the bottom in
    // the south-west; the index TSTF colours them as its first and last time-step.
    const glm::vec3 first = normalisedHue(render.scene.indexTstf.atStep(0).color);
    const glm::vec3 last = normalisedHue(render.scene.indexTstf.atStep(2).color);
    const glm::vec3 middle = normalisedHue(render.scene.indexTstf.atStep(1).color);
    const std::vector<glm::vec3> hues{first, middle, last};
    const Region northWest = regionNearest(render.image, first, hues);
    const Region southWestDeep = regionNearest(render.image, last, hues);
    ASSERT_GT(northWest.pixels, 20);
    ASSERT_GT(southWestDeep.pixels, 20);
    EXPECT_LT(northWest.centroid.x, kSize / 2.0) << "the north-west feature is left of the centre";
    EXPECT_LT(northWest.centroid.y, kSize / 2.0) << "the north-west surface feature is in the upper half";
    EXPECT_GT(southWestDeep.centroid.y, northWest.centroid.y + kSize / 4.0)
        << "the deep southern feature is well below the northern surface one";
    // Land (the fill value in the south-east) is transparent: the lower-right corner shows the background.
    EXPECT_TRUE(isBackground(render.image.at(kSize - 3, kSize - 3)));
}

TEST(AutomaticSceneRender, EachTimeStepOfAMovingBlobHasItsOwnColour) {
    const auto file = sampleFolder() / "moving-blob.nii";
    testdata::writeMovingBlobNifti(file);
    const AutomaticRender render = renderAutomatically(file);
    // Along the middle row: four blobs, one per time-step, as runs of covered pixels.
    std::vector<glm::vec3> runColours;
    std::vector<int> runLengths;
    bool inRun = false;
    glm::dvec3 sum(0.0);
    int length = 0;
    const int row = kSize / 2;
    for (int x = 0; x <= kSize; ++x) {
        const bool covered = x < kSize && render.image.at(x, row).a > 0.15f;
        if (covered) {
            const glm::vec4 pixel = render.image.at(x, row);
            sum += glm::dvec3(glm::vec3(pixel) / pixel.a);
            ++length;
        } else if (inRun) {
            runColours.push_back(glm::vec3(sum / double(length)));
            runLengths.push_back(length);
            sum = glm::dvec3(0.0);
            length = 0;
        }
        inRun = covered;
    }
    ASSERT_EQ(runColours.size(), 4u) << "four separate blobs on the middle row";
    for (std::size_t a = 0; a < 4; ++a)
        for (std::size_t b = a + 1; b < 4; ++b)
            EXPECT_GT(glm::distance(runColours[a], runColours[b]), 0.05f) << "blobs " << a << " and " << b;
    // The blob moves toward the patient's right, which a viewer facing the patient sees on the left:
    // the last time-step is the leftmost blob, the first the rightmost.
    const glm::vec3 first = glm::vec3(render.scene.indexTstf.atStep(0).color);
    const glm::vec3 last = glm::vec3(render.scene.indexTstf.atStep(3).color);
    EXPECT_LT(glm::distance(normalisedHue(runColours.back()), normalisedHue(first)),
              glm::distance(normalisedHue(runColours.back()), normalisedHue(last)));
    EXPECT_LT(glm::distance(normalisedHue(runColours.front()), normalisedHue(last)),
              glm::distance(normalisedHue(runColours.front()), normalisedHue(first)));
}

TEST(AutomaticSceneRender, MaxDensityChangeDiffersFromTemporalMip) {
    const auto file = sampleFolder() / "moving-blob-change.nii";
    testdata::writeMovingBlobNifti(file);
    const Image mip = renderAutomatically(file).image;
    const Image change = renderAutomatically(file, compositorNamed("temporal-max-change")).image;
    int different = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            if (glm::distance(mip.at(x, y), change.at(x, y)) > 0.05f) ++different;
    EXPECT_GT(different, kSize * kSize / 50) << "at least 2 % of the pixels differ";
}

TEST(AutomaticSceneRender, AirAroundACtIsTransparent) {
    const auto file = sampleFolder() / "ct-phantom.nii";
    testdata::writeCtPhantom(file);
    const AutomaticRender render = renderAutomatically(file);
    // The corners see only air (-1000 HU): exactly the (transparent) background.
    for (const glm::ivec2 corner : {glm::ivec2(1, 1), glm::ivec2(kSize - 2, 1), glm::ivec2(1, kSize - 2),
                                    glm::ivec2(kSize - 2, kSize - 2)})
        EXPECT_TRUE(isBackground(render.image.at(corner.x, corner.y))) << "corner " << corner.x << ", " << corner.y;
    // The spine (bone, 700 HU) runs up the middle of the front view, more opaque than the soft
    // tissue beside it. Neither changes over time, so both keep 0.35 of the STF's opacity on
    // boundaries, a quarter of that inside (measured 0.170 and 0.052 here; above 0.3 for the spine
    // before unchanged places were faint).
    const float spine = render.image.at(kSize / 2, kSize / 2).a;
    const float tissue = render.image.at(kSize / 2 - kSize / 6, kSize / 2).a;
    EXPECT_GT(spine, 0.12f);
    EXPECT_GT(spine, 2.5f * tissue);
}

}  // namespace
}  // namespace tstyles::testing
