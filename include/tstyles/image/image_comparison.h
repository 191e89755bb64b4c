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

// One of the pixels that differ most: where it is and what both images hold there (stored RGBA).
struct WorstPixel {
    glm::ivec2 position{0};
    int delta = 0;  // its largest channel difference, 1/255 steps
    glm::vec4 expected{0.0f};
    glm::vec4 actual{0.0f};
};

struct ImageDifference {
    // Differences in 1/255 steps of the stored RGBA values (premultiplied, as rendered), not of the
    // straight colour over black: goldens are 8-bit files of exactly these values, so one step is the
    // smallest change a file can show, and a change in alpha alone (a background that became
    // transparent) counts. Values are clamped to [0, 1] first: float (EXR) images brighter than 1
    // compare as 1.
    std::array<int, 4> maxChannelDelta{};  // R, G, B, A
    int maxDelta = 0;                      // the largest of them
    double meanDelta = 0.0;                // over all channels of all pixels
    double failingFraction = 0.0;          // share of pixels with a channel delta above the pixel threshold
    // Mean SSIM (Wang, Bovik, Sheikh and Simoncelli 2004) of the luma of the colours composited over
    // black: 11x11 Gaussian window, sigma 1.5, C1 = (0.01 L)^2, C2 = (0.03 L)^2. 1 for identical images.
    double ssim = 1.0;
    std::vector<WorstPixel> worstPixels;  // up to 5, largest delta first (earliest in row order on ties)
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
inline bool within(const ImageDifference& difference, const ComparisonThresholds& thresholds) {
    return thresholdsExceeded(difference, thresholds).empty();
}

// |actual - expected| per channel, scaled by `gain` for visibility, alpha 1.
Image differenceImage(const Image& actual, const Image& expected, float gain);
// The largest channel difference per pixel through a black-purple-orange-yellow-white ramp, full
// at `fullScale` steps of 1/255.
Image differenceHeatMap(const Image& actual, const Image& expected, int fullScale);
// expected | actual | heat map, composited over a grey checkerboard so that alpha shows.
Image sideBySide(const Image& expected, const Image& actual, const Image& heatMap);

std::string describe(const ImageDifference& difference);

}  // namespace tstyles
