// Comparing two images as a regression check sees them: 8-bit differences per channel (what PNG
// files store), the share of pixels beyond a threshold, the mean difference, and SSIM, a perceptual
// metric; with thresholds, a heat map of the difference and an expected | actual | difference
// picture. `tstyles compare` and the project's own golden tests use this one implementation.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/image/image.h"

namespace tstyles {

struct ImageDifference {
    // Differences in 1/255 steps of the stored RGBA values (premultiplied, as rendered).
    std::array<int, 4> maxChannelDelta{};  // R, G, B, A
    int maxDelta = 0;                      // the largest of them
    double meanDelta = 0.0;                // over all channels of all pixels
    double failingFraction = 0.0;          // share of pixels with a channel delta above the pixel threshold
    // Mean SSIM (Wang, Bovik, Sheikh and Simoncelli 2004) of the luma of the colours composited over
    // black: 11x11 Gaussian window, sigma 1.5, C1 = (0.01 L)^2, C2 = (0.03 L)^2. 1 for identical images.
    double ssim = 1.0;
    std::vector<glm::ivec2> worstPixels;  // up to 5, largest delta first
    std::vector<int> worstDeltas;         // their largest channel delta
};

// Images of the same size (the caller checks and reports sizes). `pixelThreshold`: a pixel fails
// when any channel differs by more than this many 1/255 steps.
ImageDifference compareImages(const Image& actual, const Image& expected, int pixelThreshold);

double structuralSimilarity(const Image& actual, const Image& expected);

// What a regression check accepts. The defaults suit one driver against itself (llvmpipe run to
// run is bit-identical, so anything beyond rounding is a change): docs/ci.md.
struct ComparisonThresholds {
    int maxDelta = 2;                  // 1/255 steps
    int pixelThreshold = 1;            // a pixel counts as failing above this
    double maxFailingFraction = 0.001; // 0.1 % of the pixels
    double maxMeanDelta = 0.05;        // 1/255 steps
    double minSsim = 0.99;
};
// Each threshold the difference exceeds, in words ("max delta 7/255 > 2/255"); empty: within.
std::vector<std::string> thresholdsExceeded(const ImageDifference& difference, const ComparisonThresholds& thresholds);

// |actual - expected| per channel, scaled by `gain` for visibility, alpha 1.
Image differenceImage(const Image& actual, const Image& expected, float gain);
// The largest channel difference per pixel through a black-purple-orange-yellow-white ramp, full
// at `fullScale` steps of 1/255.
Image differenceHeatMap(const Image& actual, const Image& expected, int fullScale);
// expected | actual | heat map, composited over a grey checkerboard so that alpha shows.
Image sideBySide(const Image& expected, const Image& actual, const Image& heatMap);

std::string describe(const ImageDifference& difference);

}  // namespace tstyles
