// Text through FreeType: anti-aliased glyphs of a TrueType font (DejaVu Sans from Debian's
// fonts-dejavu-core by default), measured and laid out along a baseline, UTF-8 in.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

namespace tstyles {

// One glyph's coverage bitmap (0..255 per pixel), placed relative to the pen on the baseline.
struct GlyphBitmap {
    int width = 0;
    int height = 0;
    int left = 0;  // from the pen to the bitmap's left edge
    int top = 0;   // from the baseline up to the bitmap's top row
    double advance = 0.0;
    std::vector<std::uint8_t> coverage;
};

class Font {
public:
    // DejaVu Sans, or the .ttf that TSTYLES_FONT names. InputError naming the file (and the Debian
    // package that holds the default) when it is missing.
    static Font openDefault();
    explicit Font(const std::filesystem::path& file);
    ~Font();
    Font(Font&& other) noexcept;
    Font& operator=(Font&& other) noexcept;
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    // Width of the text's advance, and the font's ascent and descent (positive), in pixels.
    double width(std::string_view utf8, int pixelSize) const;
    double ascent(int pixelSize) const;
    double descent(int pixelSize) const;
    // Each glyph of the text with the pen position (from the text's origin) it is drawn at.
    void forEachGlyph(std::string_view utf8, int pixelSize,
                      const std::function<void(const GlyphBitmap&, double penX)>& draw) const;

private:
    struct Faces;
    std::unique_ptr<Faces> faces_;
    const GlyphBitmap& glyph(char32_t codepoint, int pixelSize) const;
    // Rendered glyphs, kept: a legend draws the same digits over and over. Caching does not change
    // what the Font draws, so it is filled from const members.
    mutable std::map<std::pair<char32_t, int>, GlyphBitmap> cache_;
};

// The code points of UTF-8 text; a malformed byte reads as U+FFFD.
std::vector<char32_t> decodeUtf8(std::string_view utf8);

}  // namespace tstyles
