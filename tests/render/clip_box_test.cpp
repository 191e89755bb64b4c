// FrameOptions::clipBox, which a distributed render's process uses for its block: a ray's segments
// whose middles lie inside the box are rendered (here the box's faces sit on the sample lattice, so
// that is Beer-Lambert over the clipped thickness), and the frames of two halves composited front
// over back give the whole.
#include <gtest/gtest.h>

#include "render_test_support.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 64;
constexpr double kViewHeight = 2.0;
constexpr float kTolerance = 2e-3f;  // as AnalyticRender: 16-bit densities, 1024-entry tables

struct ClipCase {
    const Series series = makeSeries({constantBox({0.0, 0.0, 0.0}, 1.0f)});
    const glm::dvec2 centre{0.35, 0.35};
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    ClipCase() {
        scene.stf.curve = constantFunction({1.0, 0.5, 0.25}, 0.05);
        scene.finalMode = FinalMode::Stf;
    }
    Image render(std::optional<Bounds> clip) const {
        FrameOptions options;
        options.clipBox = clip;
        return renderSeries(series, scene, options);
    }
    glm::ivec2 pixel(glm::dvec2 world) const { return pixelOf(world, centre, kViewHeight, kSize); }
};

void expectNear(glm::vec4 actual, glm::vec4 expected, const char* what) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(actual[c], expected[c], kTolerance) << what << " channel " << c;
}

glm::vec4 slab(double thickness) {
    const float alpha = float(slabOpacity(0.05, thickness));
    return {1.0f * alpha, 0.5f * alpha, 0.25f * alpha, alpha};
}

TEST(ClipBox, RaysAreRenderedOnlyInsideTheBox) {
    const ClipCase clip;
    // The box is 0.7 thick along z; keep z in [0.2, 0.45] and x below 0.35.
    const Image image = clip.render(Bounds{{-1.0, -1.0, 0.2}, {0.35, 2.0, 0.45}});
    const glm::ivec2 inside = clip.pixel({0.2, 0.35});
    const glm::ivec2 outside = clip.pixel({0.5, 0.35});
    expectNear(image.at(inside.x, inside.y), slab(0.25), "inside the clip box");
    expectNear(image.at(outside.x, outside.y), glm::vec4(0.0f), "beside the clip box");
}

TEST(ClipBox, FrontAndBackHalvesCompositeToTheWhole) {
    const ClipCase clip;
    const Image whole = clip.render(std::nullopt);
    // The camera looks down -z: the upper half in z is in front.
    const Image front = clip.render(Bounds{{-9.0, -9.0, 0.3}, {9.0, 9.0, 9.0}});
    const Image back = clip.render(Bounds{{-9.0, -9.0, -9.0}, {9.0, 9.0, 0.3}});
    for (glm::dvec2 world : {glm::dvec2(0.35, 0.35), glm::dvec2(0.05, 0.6), glm::dvec2(0.66, 0.1)}) {
        const glm::ivec2 pixel = clip.pixel(world);
        const glm::vec4 f = front.at(pixel.x, pixel.y);
        const glm::vec4 composited = f + (1.0f - f.a) * back.at(pixel.x, pixel.y);
        expectNear(composited, whole.at(pixel.x, pixel.y), "front over back");
        expectNear(whole.at(pixel.x, pixel.y), slab(kConstantBoxWidth), "whole slab");
        expectNear(f, slab(0.4), "front part (z 0.3 to 0.7)");
    }
}

}  // namespace
}  // namespace tstyles::testing
