// Shared set-up for render tests: one headless context per test process (backend from
// TSTYLES_TEST_BACKEND: egl, osmesa or auto), synthetic series built in memory, and cameras that
// look straight down an axis so that closed-form expectations are easy to state.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/image/image.h"
#include "tstyles/render/renderer.h"
#include "tstyles/scene/scene.h"

namespace tstyles::testing {

// The renderer of this test process (the context is made on first use).
Renderer& testRenderer();
std::string testBackendDescription();

struct BoxSpec {
    glm::ivec3 dims{8, 8, 8};
    glm::dvec3 spacing{0.1};
    glm::dvec3 origin{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    std::function<float(glm::ivec3)> density = [](glm::ivec3) { return 1.0f; };
    std::optional<std::function<bool(glm::ivec3)>> mask;
};

// A box of 8x8x8 samples 0.1 apart with one density everywhere: kConstantBoxWidth wide, and its
// series' reference length (the finest spacing) is kConstantBoxSpacing.
BoxSpec constantBox(glm::dvec3 origin, float density);
inline constexpr double kConstantBoxWidth = 0.7;
inline constexpr double kConstantBoxSpacing = 0.1;

// The opacity of a slab `thickness` thick whose transfer function gives `opacityPerReference` per
// reference length (Beer-Lambert with the renderer's opacity correction).
double slabOpacity(double opacityPerReference, double thickness, double referenceLength = kConstantBoxSpacing);

// A series with one time-step per box, value range [0, 1], times 0, 1, 2, ...
Series makeSeries(const std::vector<BoxSpec>& boxes);

// A scene with an orthographic camera looking down -z at (centre.x, centre.y), showing `viewHeight`
// world units vertically, a transparent background, and STF / TSTFs left to the test.
Scene orthographicSceneLookingDownZ(glm::dvec2 centre, double viewHeight, int size);

// The series of a manifest, loaded once per test process.
const Series& loadSeriesOnce(const std::filesystem::path& manifest);

// Renders `series` with `scene` (uploads the series each call).
Image renderSeries(const Series& series, const Scene& scene);
// The same with frame options (packed or not, naive or not, solo...); the size is the scene's.
Image renderSeries(const Series& series, const Scene& scene, FrameOptions options);
// Draws `scene` with the series that testRenderer() already holds (`seriesBounds`: its world
// bounds), at the scene's size, without uploading the series again.
Image drawWithCurrentSeries(const Scene& scene, const Bounds& seriesBounds, FrameOptions options);

// Pixel (column, row from the top) where world point (x, y) lands in a scene made by
// orthographicSceneLookingDownZ.
glm::ivec2 pixelOf(glm::dvec2 world, glm::dvec2 centre, double viewHeight, int size);

// A transfer function with one constant colour and opacity.
TransferFunction1D constantFunction(glm::dvec3 color, double opacity);

// A folder of this test process for style images (ctest runs the EGL and OSMesa variants at once).
std::filesystem::path styleImageFolder();
// A lit-sphere style image <name>.png in styleImageFolder(), drawn from a function of the sphere
// normal's (x, y), y up; returns its path.
std::string writeStyle(const std::string& name, int width, int height,
                       const std::function<glm::vec4(glm::vec2)>& colorAt);

}  // namespace tstyles::testing
