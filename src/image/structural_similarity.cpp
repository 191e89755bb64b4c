// Mean SSIM (Wang, Bovik, Sheikh and Simoncelli, "Image quality assessment: from error visibility to
// structural similarity", 2004) with the paper's constants, on luma in [0, 255].
#include <algorithm>
#include <cmath>
#include <vector>

#include "tstyles/image/image_comparison.h"

namespace tstyles {
namespace {

constexpr double kDynamicRange = 255.0;
constexpr double kC1 = (0.01 * kDynamicRange) * (0.01 * kDynamicRange);
constexpr double kC2 = (0.03 * kDynamicRange) * (0.03 * kDynamicRange);
constexpr int kRadius = 5;  // an 11x11 window
constexpr double kSigma = 1.5;

// Rec. 709 luma of the colour composited over black (the stored premultiplied RGB), 0..255.
std::vector<double> lumaOf(const Image& image) {
    std::vector<double> luma(std::size_t(image.width) * std::size_t(image.height));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4 p = glm::clamp(image.at(x, y), 0.0f, 1.0f);
            luma[std::size_t(y) * std::size_t(image.width) + std::size_t(x)] =
                kDynamicRange * (0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b);
        }
    return luma;
}

// Separable Gaussian filter over the positions where the whole window fits ("valid").
std::vector<double> filtered(const std::vector<double>& values, int width, int height, const std::vector<double>& kernel,
                             int radius) {
    const int outWidth = width - 2 * radius;
    const int outHeight = height - 2 * radius;
    std::vector<double> rows(std::size_t(outWidth) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < outWidth; ++x) {
            double sum = 0.0;
            for (int k = 0; k <= 2 * radius; ++k) sum += kernel[std::size_t(k)] * values[std::size_t(y * width + x + k)];
            rows[std::size_t(y * outWidth + x)] = sum;
        }
    std::vector<double> result(std::size_t(outWidth) * std::size_t(outHeight));
    for (int y = 0; y < outHeight; ++y)
        for (int x = 0; x < outWidth; ++x) {
            double sum = 0.0;
            for (int k = 0; k <= 2 * radius; ++k) sum += kernel[std::size_t(k)] * rows[std::size_t((y + k) * outWidth + x)];
            result[std::size_t(y * outWidth + x)] = sum;
        }
    return result;
}

}  // namespace

double structuralSimilarity(const Image& actual, const Image& expected) {
    const int width = actual.width;
    const int height = actual.height;
    // A picture smaller than the window is one window, as large as fits.
    const int radius = std::min(kRadius, (std::min(width, height) - 1) / 2);
    if (radius < 0) return 1.0;
    std::vector<double> kernel;
    double total = 0.0;
    for (int k = -radius; k <= radius; ++k) {
        kernel.push_back(std::exp(-0.5 * k * k / (kSigma * kSigma)));
        total += kernel.back();
    }
    for (double& weight : kernel) weight /= total;
    const std::vector<double> x = lumaOf(actual);
    const std::vector<double> y = lumaOf(expected);
    std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) xx[i] = x[i] * x[i], yy[i] = y[i] * y[i], xy[i] = x[i] * y[i];
    const auto muX = filtered(x, width, height, kernel, radius);
    const auto muY = filtered(y, width, height, kernel, radius);
    const auto meanXX = filtered(xx, width, height, kernel, radius);
    const auto meanYY = filtered(yy, width, height, kernel, radius);
    const auto meanXY = filtered(xy, width, height, kernel, radius);
    double sum = 0.0;
    for (std::size_t i = 0; i < muX.size(); ++i) {
        const double varX = meanXX[i] - muX[i] * muX[i];
        const double varY = meanYY[i] - muY[i] * muY[i];
        const double covariance = meanXY[i] - muX[i] * muY[i];
        sum += ((2.0 * muX[i] * muY[i] + kC1) * (2.0 * covariance + kC2)) /
               ((muX[i] * muX[i] + muY[i] * muY[i] + kC1) * (varX + varY + kC2));
    }
    return muX.empty() ? 1.0 : sum / double(muX.size());
}

}  // namespace tstyles
