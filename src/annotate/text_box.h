// A line of text measured by the pixels its ink touches, so that the layout can keep texts apart to
// the pixel; and names shortened with an ellipsis to a width. Private to src/annotate.
#pragma once

#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "tstyles/annotate/canvas.h"
#include "tstyles/annotate/font.h"

namespace tstyles {

// Text drawn with its baseline's left end at `origin` (whole pixels, as Canvas::drawText rounds
// it); `rect` holds the font's line (advance by ascent and descent) and every pixel of ink, with a
// pixel to spare on each side, so that texts whose rectangles touch keep a clear pixel between
// them.
struct TextBox {
    std::string text;
    int pixels = 13;
    glm::dvec2 origin{0.0};
    Rect rect;
};

// The box of `text` whose rectangle's centre is nearest `centre`.
TextBox textCentredAt(const Font& font, std::string text, int pixels, glm::dvec2 centre);
// The box of `text` drawn from `origin` (rounded to whole pixels).
TextBox textFrom(const Font& font, std::string text, int pixels, glm::dvec2 origin);
// The same box moved by whole pixels.
TextBox moved(TextBox box, glm::ivec2 by);

void drawTextBox(Canvas& canvas, const Font& font, const TextBox& box, const glm::vec4& colour);

// `text` as it is where its advance fits `maxWidth`, else cut at a code point and ended with
// "\u2026"; empty where not even one character and the ellipsis fit.
std::string shortenToWidth(const Font& font, const std::string& text, int pixels, double maxWidth);

}  // namespace tstyles
