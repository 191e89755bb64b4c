// Rays that the driver cuts short are counted, so that front ends can say that an image is
// incomplete: llvmpipe ends every loop of a shader invocation once 65535 loop passes have run in
// it (docs/architecture.md, "Limits: samples per ray on llvmpipe"). A ray that reaches its exit is
// never counted.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "render_test_support.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 16;
constexpr double kViewHeight = 1.0;

bool driverIsLlvmpipe() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name != nullptr && std::string(name).find("llvmpipe") != std::string::npos;
}

TEST(CutShortRays, AreCountedWhenTheDriverEndsTheRayMarchEarly) {
    const Series series = makeSeries({constantBox({0.0, 0.0, 0.0}, 1.0f)});
    const glm::dvec2 centre(0.35, 0.35);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    // Faint, so that no ray reaches the termination opacity: 1 - 0.999^7 through the slab.
    const double alpha = 0.001;
    scene.stf.curve = constantFunction(glm::dvec3(1.0), alpha);
    scene.finalMode = FinalMode::Stf;
    const double slabAlpha = slabOpacity(alpha, kConstantBoxWidth);
    const glm::ivec2 middle = pixelOf(centre, centre, kViewHeight, kSize);

    // Every ray of the slab reaches its exit: none is counted, and the slab has its full opacity.
    scene.raycast.step = 0.05;
    const Image complete = renderSeries(series, scene);
    EXPECT_EQ(testRenderer().lastCutShortRays(), 0u);
    EXPECT_NEAR(complete.at(middle.x, middle.y).a, slabAlpha, 2e-4);

    // 300 000 samples per ray through the slab, far past llvmpipe's 65535 loop passes.
    scene.raycast.step = kConstantBoxWidth / 300000.0;
    const Image cut = renderSeries(series, scene);
    if (!driverIsLlvmpipe()) {
        // Drivers without such a limit take every sample.
        EXPECT_EQ(testRenderer().lastCutShortRays(), 0u);
        return;
    }
    // Every pixel of the slab's interior is cut short, and it shows: the pixel has only part of
    // the slab's opacity.
    const int covered = int(std::floor(kConstantBoxWidth / kViewHeight * kSize)) - 1;
    EXPECT_GE(testRenderer().lastCutShortRays(), std::uint32_t(covered * covered));
    EXPECT_LT(cut.at(middle.x, middle.y).a, 0.5 * slabAlpha);
}

}  // namespace
}  // namespace tstyles::testing
