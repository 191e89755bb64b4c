// The scissor rectangle of the raycasting pass (render/covered_pixels.h): known projections.
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "tstyles/render/covered_pixels.h"

namespace tstyles {
namespace {

// An orthographic view of [-1,1]^2 onto 100x100 pixels: world x, y map to pixels 50 * (x + 1).
const glm::dmat4 kOrthographic = glm::ortho(-1.0, 1.0, -1.0, 1.0, 0.1, 10.0);

TEST(CoveredPixels, OrthographicBoxGivesItsPixelsAndAMarginOfOne) {
    const Bounds box{{-0.5, -0.2, -3.0}, {0.5, 0.6, -2.0}};
    const PixelRectangle covered = coveredPixels(box, kOrthographic, {100, 100});
    // x from 25 to 75, y from 40 to 80; one pixel of margin each side.
    EXPECT_EQ(covered.offset, glm::ivec2(24, 39));
    EXPECT_EQ(covered.size, glm::ivec2(52, 42));
}

TEST(CoveredPixels, IsClampedToTheViewport) {
    const Bounds box{{-5.0, 0.5, -3.0}, {0.0, 5.0, -2.0}};
    const PixelRectangle covered = coveredPixels(box, kOrthographic, {100, 100});
    EXPECT_EQ(covered.offset, glm::ivec2(0, 74));
    EXPECT_EQ(covered.size, glm::ivec2(51, 26));
}

TEST(CoveredPixels, BoxOutsideTheViewCoversNothing) {
    const Bounds box{{2.0, 2.0, -3.0}, {3.0, 3.0, -2.0}};
    const PixelRectangle covered = coveredPixels(box, kOrthographic, {100, 100});
    EXPECT_EQ(covered.size.x * covered.size.y, 0);
}

TEST(CoveredPixels, BoxAroundTheEyeCoversTheWholeViewport) {
    const glm::dmat4 perspective = glm::perspective(glm::radians(60.0), 1.0, 0.1, 10.0);
    const Bounds box{{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}};  // the eye sits at the origin, inside
    const PixelRectangle covered = coveredPixels(box, perspective, {64, 48});
    EXPECT_EQ(covered.offset, glm::ivec2(0, 0));
    EXPECT_EQ(covered.size, glm::ivec2(64, 48));
}

}  // namespace
}  // namespace tstyles
