// Constant boxes stacked in time, and their pixels read back (stacked_boxes.h).
#include "stacked_boxes.h"

#include <gtest/gtest.h>

namespace tstyles::testing {

Series stackedBoxes(const std::vector<float>& densities) {
    std::vector<BoxSpec> boxes;
    for (float density : densities) boxes.push_back(constantBox({0, 0, 0}, density));
    return makeSeries(boxes);
}

void expectPixelNear(const Image& image, glm::ivec2 pixel, glm::vec4 expected, const std::string& what) {
    const glm::vec4 actual = image.at(pixel.x, pixel.y);
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(actual[c], expected[c], kStackTolerance)
            << what << " at pixel (" << pixel.x << ", " << pixel.y << ") channel " << c;
}

void expectStackPixel(const Image& image, glm::dvec2 world, glm::vec4 expected, const std::string& what) {
    expectPixelNear(image, pixelOf(world, kStackCentre, kStackViewHeight, kStackSize), expected, what);
}

}  // namespace tstyles::testing
