// Image differences in 8-bit steps, thresholds, and pictures of the difference.
#include "tstyles/image/image_comparison.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tstyles {
namespace {

int toByte(float value) { return int(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); }

std::string number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

}  // namespace

ImageDifference compareImages(const Image& actual, const Image& expected, int pixelThreshold) {
    if (actual.width != expected.width || actual.height != expected.height)
        throw std::invalid_argument("compareImages: the images differ in size");
    ImageDifference result;
    std::vector<std::pair<int, glm::ivec2>> deltas;
    long long sum = 0;
    long long failing = 0;
    for (int y = 0; y < actual.height; ++y)
        for (int x = 0; x < actual.width; ++x) {
            const glm::vec4 a = actual.at(x, y);
            const glm::vec4 e = expected.at(x, y);
            int pixelMax = 0;
            for (int c = 0; c < 4; ++c) {
                const int delta = std::abs(toByte(a[c]) - toByte(e[c]));
                sum += delta;
                pixelMax = std::max(pixelMax, delta);
                result.maxChannelDelta[std::size_t(c)] = std::max(result.maxChannelDelta[std::size_t(c)], delta);
            }
            result.maxDelta = std::max(result.maxDelta, pixelMax);
            if (pixelMax > pixelThreshold) ++failing;
            if (pixelMax > 0) deltas.push_back({pixelMax, {x, y}});
        }
    const double pixels = std::max(double(actual.width) * double(actual.height), 1.0);
    result.meanDelta = double(sum) / (pixels * 4.0);
    result.failingFraction = double(failing) / pixels;
    std::stable_sort(deltas.begin(), deltas.end(), [](const auto& l, const auto& r) { return l.first > r.first; });
    for (std::size_t i = 0; i < std::min<std::size_t>(5, deltas.size()); ++i) {
        const glm::ivec2 at = deltas[i].second;
        result.worstPixels.push_back({at, deltas[i].first, expected.at(at.x, at.y), actual.at(at.x, at.y)});
    }
    result.ssim = structuralSimilarity(actual, expected);
    return result;
}

std::vector<std::string> thresholdsExceeded(const ImageDifference& difference, const ComparisonThresholds& thresholds) {
    std::vector<std::string> exceeded;
    if (difference.maxDelta > thresholds.maxDelta)
        exceeded.push_back("max delta " + std::to_string(difference.maxDelta) + "/255 > " +
                           std::to_string(thresholds.maxDelta) + "/255");
    if (difference.failingFraction > thresholds.maxFailingFraction)
        exceeded.push_back("pixels beyond " + std::to_string(thresholds.pixelThreshold) + "/255: " +
                           number(100.0 * difference.failingFraction) + " % > " +
                           number(100.0 * thresholds.maxFailingFraction) + " %");
    if (difference.meanDelta > thresholds.maxMeanDelta)
        exceeded.push_back("mean delta " + number(difference.meanDelta) + "/255 > " + number(thresholds.maxMeanDelta) +
                           "/255");
    if (difference.ssim < thresholds.minSsim)
        exceeded.push_back("SSIM " + number(difference.ssim) + " < " + number(thresholds.minSsim));
    return exceeded;
}

Image differenceImage(const Image& actual, const Image& expected, float gain) {
    Image difference(actual.width, actual.height);
    for (int y = 0; y < actual.height; ++y)
        for (int x = 0; x < actual.width; ++x) {
            const glm::vec4 delta = glm::abs(actual.at(x, y) - expected.at(x, y)) * gain;
            difference.set(x, y, glm::vec4(glm::min(glm::vec3(delta), glm::vec3(1.0f)), 1.0f));
        }
    return difference;
}

Image differenceHeatMap(const Image& actual, const Image& expected, int fullScale) {
    // Black, purple, orange, yellow, white: dark where nothing changed, bright where most did.
    constexpr std::array<glm::vec3, 5> ramp{glm::vec3(0.0f), glm::vec3(0.35f, 0.05f, 0.5f), glm::vec3(0.9f, 0.35f, 0.1f),
                                            glm::vec3(1.0f, 0.85f, 0.2f), glm::vec3(1.0f)};
    Image heat(actual.width, actual.height);
    for (int y = 0; y < actual.height; ++y)
        for (int x = 0; x < actual.width; ++x) {
            int delta = 0;
            for (int c = 0; c < 4; ++c)
                delta = std::max(delta, std::abs(toByte(actual.at(x, y)[c]) - toByte(expected.at(x, y)[c])));
            const float t = std::clamp(float(delta) / float(std::max(fullScale, 1)), 0.0f, 1.0f) * float(ramp.size() - 1);
            const std::size_t low = std::min(std::size_t(t), ramp.size() - 2);
            heat.set(x, y, glm::vec4(glm::mix(ramp[low], ramp[low + 1], t - float(low)), 1.0f));
        }
    return heat;
}

Image sideBySide(const Image& expected, const Image& actual, const Image& heatMap) {
    constexpr int kGap = 4;
    const int width = expected.width;
    Image combined(3 * width + 2 * kGap, expected.height);
    const Image* parts[3] = {&expected, &actual, &heatMap};
    for (int part = 0; part < 3; ++part)
        for (int y = 0; y < expected.height; ++y)
            for (int x = 0; x < width; ++x) {
                const float checker = ((x / 8 + y / 8) % 2 == 0) ? 0.4f : 0.6f;
                const glm::vec4 pixel = parts[part]->at(x, y);
                combined.set(part * (width + kGap) + x, y,
                             glm::vec4(glm::vec3(pixel) + glm::vec3(checker) * (1.0f - pixel.a), 1.0f));
            }
    return combined;
}

std::string describe(const ImageDifference& difference) {
    std::ostringstream text;
    text << "max delta " << difference.maxDelta << "/255 (R " << difference.maxChannelDelta[0] << ", G "
         << difference.maxChannelDelta[1] << ", B " << difference.maxChannelDelta[2] << ", A "
         << difference.maxChannelDelta[3] << "), mean delta " << difference.meanDelta << "/255, failing pixels "
         << difference.failingFraction * 100.0 << " %, SSIM " << difference.ssim << "; worst at";
    for (const WorstPixel& worst : difference.worstPixels)
        text << " (" << worst.position.x << ", " << worst.position.y << ": " << worst.delta << ")";
    return text.str();
}

}  // namespace tstyles
