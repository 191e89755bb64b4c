// Image differences for the golden-image tests.
#include "image_comparison.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tstyles::testing {
namespace {
int toByte(float value) { return int(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); }
}  // namespace

ImageDifference compareImages(const Image& actual, const Image& expected, int pixelThreshold) {
    if (actual.width != expected.width || actual.height != expected.height)
        throw std::runtime_error("image sizes differ");
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
            }
            result.maxDelta = std::max(result.maxDelta, pixelMax);
            if (pixelMax > pixelThreshold) ++failing;
            if (pixelMax > 0) deltas.push_back({pixelMax, {x, y}});
        }
    const double pixels = double(actual.width) * double(actual.height);
    result.meanDelta = double(sum) / (pixels * 4.0);
    result.failingFraction = double(failing) / pixels;
    std::stable_sort(deltas.begin(), deltas.end(), [](const auto& l, const auto& r) { return l.first > r.first; });
    for (std::size_t i = 0; i < std::min<std::size_t>(5, deltas.size()); ++i) result.worstPixels.push_back(deltas[i].second);
    return result;
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

std::string describe(const ImageDifference& difference) {
    std::ostringstream text;
    text << "max delta " << difference.maxDelta << "/255, mean delta " << difference.meanDelta
         << "/255, failing pixels " << difference.failingFraction * 100.0 << " %; worst at";
    for (const auto& pixel : difference.worstPixels) text << " (" << pixel.x << ", " << pixel.y << ")";
    return text.str();
}

}  // namespace tstyles::testing
