// Comparing a rendered image with a golden image in 8-bit units, as the PNG stores it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/image/image.h"

namespace tstyles::testing {

struct ImageDifference {
    int maxDelta = 0;            // largest channel difference, in 1/255 steps
    double meanDelta = 0.0;      // mean over all channels of all pixels, in 1/255 steps
    double failingFraction = 0;  // share of pixels with a channel difference above the threshold
    std::vector<glm::ivec2> worstPixels;  // up to 5, largest difference first
};

// `pixelThreshold`: a pixel fails when any channel differs by more than this many 1/255 steps.
ImageDifference compareImages(const Image& actual, const Image& expected, int pixelThreshold);

// |actual - expected| per channel, scaled by `gain` for visibility, alpha 1.
Image differenceImage(const Image& actual, const Image& expected, float gain);

std::string describe(const ImageDifference& difference);

}  // namespace tstyles::testing
