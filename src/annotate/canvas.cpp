// Anti-aliased 2D drawing onto images for legends and annotations.
#include "tstyles/annotate/canvas.h"

#include <algorithm>
#include <cmath>

namespace tstyles {

void Canvas::blend(int x, int y, float coverage, const glm::vec4& colour) {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || coverage <= 0.0f) return;
    const float alpha = colour.a * std::min(coverage, 1.0f);
    const glm::vec4 source(glm::vec3(colour) * alpha, alpha);
    image_.set(x, y, source + image_.at(x, y) * (1.0f - alpha));
}

void Canvas::fillRect(const Rect& rect, const glm::vec4& colour) {
    const int x0 = int(std::floor(rect.x));
    const int y0 = int(std::floor(rect.y));
    const int x1 = int(std::ceil(rect.right()));
    const int y1 = int(std::ceil(rect.bottom()));
    for (int y = y0; y < y1; ++y) {
        const double coverY = std::min(double(y + 1), rect.bottom()) - std::max(double(y), rect.y);
        for (int x = x0; x < x1; ++x) {
            const double coverX = std::min(double(x + 1), rect.right()) - std::max(double(x), rect.x);
            blend(x, y, float(coverX * coverY), colour);
        }
    }
}

void Canvas::strokeRect(const Rect& rect, double lineWidth, const glm::vec4& colour) {
    const double w = lineWidth;
    fillRect({rect.x, rect.y, rect.width, w}, colour);
    fillRect({rect.x, rect.bottom() - w, rect.width, w}, colour);
    fillRect({rect.x, rect.y + w, w, rect.height - 2 * w}, colour);
    fillRect({rect.right() - w, rect.y + w, w, rect.height - 2 * w}, colour);
}

void Canvas::drawLine(glm::dvec2 from, glm::dvec2 to, double lineWidth, const glm::vec4& colour) {
    const glm::dvec2 along = to - from;
    const double length = glm::length(along);
    if (length == 0.0) return;
    const glm::dvec2 direction = along / length;
    const double half = 0.5 * lineWidth;
    const int x0 = int(std::floor(std::min(from.x, to.x) - half - 1));
    const int x1 = int(std::ceil(std::max(from.x, to.x) + half + 1));
    const int y0 = int(std::floor(std::min(from.y, to.y) - half - 1));
    const int y1 = int(std::ceil(std::max(from.y, to.y) + half + 1));
    for (int y = std::max(y0, 0); y <= std::min(y1, image_.height - 1); ++y)
        for (int x = std::max(x0, 0); x <= std::min(x1, image_.width - 1); ++x) {
            const glm::dvec2 offset = glm::dvec2(x + 0.5, y + 0.5) - from;
            const double t = glm::dot(offset, direction);
            const double across = std::abs(offset.x * direction.y - offset.y * direction.x);
            // A one-pixel ramp at the edges: the area of the pixel inside the band, near enough.
            const double coverAcross = std::clamp(half + 0.5 - across, 0.0, 1.0);
            const double coverAlong = std::clamp(std::min(t + 0.5, length - t + 0.5), 0.0, 1.0);
            blend(x, y, float(coverAcross * coverAlong), colour);
        }
}

void Canvas::drawText(const Font& font, std::string_view utf8, glm::dvec2 baselineStart, int pixelSize,
                      const glm::vec4& colour) {
    const int originX = int(std::lround(baselineStart.x));
    const int baseline = int(std::lround(baselineStart.y));
    font.forEachGlyph(utf8, pixelSize, [&](const GlyphBitmap& glyph, double pen) {
        const int left = originX + int(std::lround(pen)) + glyph.left;
        const int top = baseline - glyph.top;
        for (int row = 0; row < glyph.height; ++row)
            for (int column = 0; column < glyph.width; ++column)
                blend(left + column, top + row,
                      float(glyph.coverage[std::size_t(row * glyph.width + column)]) / 255.0f, colour);
    });
}

}  // namespace tstyles
