// Text measured to its ink, and shortened to a width.
#include "text_box.h"

#include <algorithm>
#include <cmath>

namespace tstyles {
namespace {

constexpr char kEllipsis[] = "\u2026";

// The pixels the text touches, from its origin: the line box (advance, ascent, descent) joined with
// the ink of every glyph, as Canvas::drawText places them (pen positions rounded), and a spare
// pixel around.
Rect extentFromOrigin(const Font& font, std::string_view text, int pixels) {
    double left = 0.0;
    double right = std::ceil(font.width(text, pixels));
    double top = -std::ceil(font.ascent(pixels));
    double bottom = std::ceil(font.descent(pixels));
    font.forEachGlyph(text, pixels, [&](const GlyphBitmap& glyph, double pen) {
        if (glyph.width <= 0 || glyph.height <= 0) return;
        const double glyphLeft = double(std::lround(pen) + glyph.left);
        left = std::min(left, glyphLeft);
        right = std::max(right, glyphLeft + glyph.width);
        top = std::min(top, double(-glyph.top));
        bottom = std::max(bottom, double(glyph.height - glyph.top));
    });
    return {left - 1.0, top - 1.0, right - left + 2.0, bottom - top + 2.0};
}

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

}  // namespace

TextBox textFrom(const Font& font, std::string text, int pixels, glm::dvec2 origin) {
    const glm::dvec2 whole(std::round(origin.x), std::round(origin.y));
    const Rect extent = extentFromOrigin(font, text, pixels);
    return {std::move(text), pixels, whole, {whole.x + extent.x, whole.y + extent.y, extent.width, extent.height}};
}

TextBox textCentredAt(const Font& font, std::string text, int pixels, glm::dvec2 centre) {
    const Rect extent = extentFromOrigin(font, text, pixels);
    const glm::dvec2 middle(extent.x + 0.5 * extent.width, extent.y + 0.5 * extent.height);
    return textFrom(font, std::move(text), pixels, centre - middle);
}

TextBox moved(TextBox box, glm::ivec2 by) {
    box.origin += glm::dvec2(by);
    box.rect.x += by.x;
    box.rect.y += by.y;
    return box;
}

void drawTextBox(Canvas& canvas, const Font& font, const TextBox& box, const glm::vec4& colour) {
    canvas.drawText(font, box.text, box.origin, box.pixels, colour);
}

std::string shortenToWidth(const Font& font, const std::string& text, int pixels, double maxWidth) {
    if (font.width(text, pixels) <= maxWidth) return text;
    std::size_t end = text.size();
    while (end > 0) {
        do --end;
        while (end > 0 && isContinuationByte(text[end]));
        std::size_t kept = end;
        while (kept > 0 && text[kept - 1] == ' ') --kept;  // "long name…", not "long …"
        const std::string shortened = text.substr(0, kept) + kEllipsis;
        if (kept > 0 && font.width(shortened, pixels) <= maxWidth) return shortened;
    }
    return {};  // an ellipsis alone says nothing
}

}  // namespace tstyles
