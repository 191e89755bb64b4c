// Tile layout, cropped projections and the adaptive preview resolution.
#include "tile_plan.h"

#include <algorithm>
#include <cmath>

namespace tstyles::viewer {

glm::ivec2 tileSizeFor(glm::ivec2 frame, int divisor) {
    divisor = std::max(divisor, 1);
    return {(frame.x + divisor - 1) / divisor, (frame.y + divisor - 1) / divisor};
}

std::vector<PixelWindow> planTiles(glm::ivec2 frame, int divisor) {
    divisor = std::max(divisor, 1);
    const glm::ivec2 tile = tileSizeFor(frame, divisor);
    std::vector<PixelWindow> tiles;
    for (int y = 0; y < divisor; ++y)
        for (int x = 0; x < divisor; ++x) {
            const glm::ivec2 offset{x * tile.x, y * tile.y};
            if (offset.x < frame.x && offset.y < frame.y) tiles.push_back({offset, tile});
        }
    const glm::dvec2 centre = glm::dvec2(frame) * 0.5;
    auto distanceToCentre = [&](const PixelWindow& window) {
        return glm::length(glm::dvec2(window.offset) + glm::dvec2(window.size) * 0.5 - centre);
    };
    std::stable_sort(tiles.begin(), tiles.end(), [&](const PixelWindow& a, const PixelWindow& b) {
        return distanceToCentre(a) < distanceToCentre(b);
    });
    return tiles;
}

glm::dmat4 cropProjection(const glm::dmat4& projection, glm::ivec2 frame, const PixelWindow& window) {
    // Normalized device x of the full frame maps to the window's own [-1, 1]:
    // ndc' = ndc * frame / size + (frame - 2 * offset - size) / size.
    const glm::dvec2 full(frame);
    const glm::dvec2 size(window.size);
    const glm::dvec2 scale = full / size;
    const glm::dvec2 shift = (full - 2.0 * glm::dvec2(window.offset) - size) / size;
    glm::dmat4 crop(1.0);
    crop[0][0] = scale.x;
    crop[1][1] = scale.y;
    crop[3][0] = shift.x;
    crop[3][1] = shift.y;
    return crop * projection;
}

View cropView(const View& view, glm::ivec2 frame, const PixelWindow& window) {
    View cropped = view;
    cropped.projectionMatrix = cropProjection(view.projectionMatrix, frame, window);
    const double halfHeight = std::tan(glm::radians(view.fovDeg) * 0.5) * double(window.size.y) / double(frame.y);
    cropped.fovDeg = glm::degrees(2.0 * std::atan(halfHeight));
    return cropped;
}

int previewDivisorFor(double lastMs, int lastDivisor, double targetMs, int maxDivisor) {
    if (!(lastMs > 0.0) || !(targetMs > 0.0)) return std::clamp(lastDivisor, 1, maxDivisor);
    // Time goes with pixels, pixels with 1 / divisor^2.
    const double ideal = double(lastDivisor) * std::sqrt(lastMs / targetMs);
    // A little hysteresis, so that the preview does not flicker between two sizes.
    int divisor = lastDivisor;
    if (ideal > double(lastDivisor) + 0.6) divisor = int(std::ceil(ideal - 0.25));
    if (ideal < double(lastDivisor) - 1.0) divisor = int(std::ceil(ideal));
    return std::clamp(divisor, 1, maxDivisor);
}

float previewStepScaleFor(int divisor) { return std::max(kPreviewStepScale, 0.5f * float(divisor)); }

}  // namespace tstyles::viewer
