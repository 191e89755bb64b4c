// Drawing over a rendered image (premultiplied RGBA floats, rows top to bottom, pixel centres at
// +0.5): filled rectangles, anti-aliased lines and text, all composited "over". Colours given to the
// canvas are straight (not premultiplied) RGBA in [0, 1].
#pragma once

#include <string_view>

#include <glm/glm.hpp>

#include "tstyles/annotate/font.h"
#include "tstyles/image/image.h"

namespace tstyles {

struct Rect {
    double x = 0.0;
    double y = 0.0;
    double width = 0.0;
    double height = 0.0;
    double right() const { return x + width; }
    double bottom() const { return y + height; }
};

class Canvas {
public:
    explicit Canvas(Image& image) : image_(image) {}
    int width() const { return image_.width; }
    int height() const { return image_.height; }

    // `colour` over the pixel with the given coverage in [0, 1].
    void blend(int x, int y, float coverage, const glm::vec4& colour);
    // Pixels partly inside get partial coverage.
    void fillRect(const Rect& rect, const glm::vec4& colour);
    void strokeRect(const Rect& rect, double lineWidth, const glm::vec4& colour);
    // A segment `lineWidth` wide with square-cut ends, coverage from the distance to it.
    void drawLine(glm::dvec2 from, glm::dvec2 to, double lineWidth, const glm::vec4& colour);
    // Text with its left end at x and its baseline at y.
    void drawText(const Font& font, std::string_view utf8, glm::dvec2 baselineStart, int pixelSize,
                  const glm::vec4& colour);

private:
    Image& image_;
};

}  // namespace tstyles
