// FreeType behind Font: one library and one face per Font, glyphs rendered in 8-bit coverage.
#include "tstyles/annotate/font.h"

#include <cstdlib>

#include <ft2build.h>
#include FT_FREETYPE_H

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace tstyles {

struct Font::Faces {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    ~Faces() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }
};

namespace {

constexpr const char* kDefaultFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

}  // namespace

std::vector<char32_t> decodeUtf8(std::string_view utf8) {
    std::vector<char32_t> codepoints;
    for (std::size_t i = 0; i < utf8.size();) {
        const auto lead = static_cast<unsigned char>(utf8[i]);
        const int length = lead < 0x80 ? 1 : (lead >> 5) == 6 ? 2 : (lead >> 4) == 14 ? 3 : (lead >> 3) == 30 ? 4 : 0;
        if (length == 0 || i + std::size_t(length) > utf8.size()) {
            codepoints.push_back(0xFFFD);
            ++i;
            continue;
        }
        char32_t codepoint = length == 1 ? lead : lead & (0x7F >> length);
        bool valid = true;
        for (int k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(utf8[i + std::size_t(k)]);
            valid = valid && (next >> 6) == 2;
            codepoint = (codepoint << 6) | (next & 0x3F);
        }
        codepoints.push_back(valid ? codepoint : 0xFFFD);
        i += valid ? std::size_t(length) : 1;
    }
    return codepoints;
}

Font Font::openDefault() {
    const char* chosen = std::getenv("TSTYLES_FONT");
    const std::filesystem::path file = chosen && *chosen ? chosen : kDefaultFont;
    if (userPathKind({"", chosen && *chosen ? "TSTYLES_FONT" : ""}, file) != PathKind::RegularFile)
        throwInputError(file, "", chosen && *chosen ? "the font that TSTYLES_FONT names does not exist"
                                                    : "the legend font is missing; install Debian's fonts-dejavu-core "
                                                      "(tools/install_dependencies.sh does)");
    return Font(file);
}

Font::Font(const std::filesystem::path& file) : faces_(std::make_unique<Faces>()) {
    if (FT_Init_FreeType(&faces_->library) != 0) throwInputError(file, "", "FreeType could not start");
    if (userPathKind({}, file) != PathKind::RegularFile) throwInputError(file, "", "no such font file");
    if (FT_New_Face(faces_->library, file.c_str(), 0, &faces_->face) != 0)
        throwInputError(file, "", "FreeType cannot read it as a font");
}

Font::~Font() = default;
Font::Font(Font&& other) noexcept = default;
Font& Font::operator=(Font&& other) noexcept = default;

const GlyphBitmap& Font::glyph(char32_t codepoint, int pixelSize) const {
    const auto key = std::pair{codepoint, pixelSize};
    if (const auto found = cache_.find(key); found != cache_.end()) return found->second;
    GlyphBitmap bitmap;
    FT_Face face = faces_->face;
    FT_Set_Pixel_Sizes(face, 0, FT_UInt(pixelSize));
    if (FT_Load_Char(face, FT_ULong(codepoint), FT_LOAD_RENDER) == 0) {
        const FT_Bitmap& rendered = face->glyph->bitmap;
        bitmap.width = int(rendered.width);
        bitmap.height = int(rendered.rows);
        bitmap.left = face->glyph->bitmap_left;
        bitmap.top = face->glyph->bitmap_top;
        bitmap.advance = double(face->glyph->advance.x) / 64.0;
        bitmap.coverage.resize(std::size_t(bitmap.width) * std::size_t(bitmap.height));
        for (int row = 0; row < bitmap.height; ++row)
            for (int column = 0; column < bitmap.width; ++column)
                bitmap.coverage[std::size_t(row * bitmap.width + column)] = rendered.buffer[row * rendered.pitch + column];
    }
    return cache_.emplace(key, std::move(bitmap)).first->second;
}

void Font::forEachGlyph(std::string_view utf8, int pixelSize,
                        const std::function<void(const GlyphBitmap&, double penX)>& draw) const {
    double pen = 0.0;
    FT_UInt previous = 0;
    for (const char32_t codepoint : decodeUtf8(utf8)) {
        const FT_UInt index = FT_Get_Char_Index(faces_->face, FT_ULong(codepoint));
        if (previous != 0 && index != 0 && FT_HAS_KERNING(faces_->face)) {
            FT_Set_Pixel_Sizes(faces_->face, 0, FT_UInt(pixelSize));
            FT_Vector kerning{};
            FT_Get_Kerning(faces_->face, previous, index, FT_KERNING_DEFAULT, &kerning);
            pen += double(kerning.x) / 64.0;
        }
        const GlyphBitmap& bitmap = glyph(codepoint, pixelSize);
        draw(bitmap, pen);
        pen += bitmap.advance;
        previous = index;
    }
}

double Font::width(std::string_view utf8, int pixelSize) const {
    double end = 0.0;
    forEachGlyph(utf8, pixelSize, [&](const GlyphBitmap& glyphBitmap, double pen) { end = pen + glyphBitmap.advance; });
    return end;
}

double Font::ascent(int pixelSize) const {
    return double(faces_->face->ascender) * pixelSize / double(faces_->face->units_per_EM);
}

double Font::descent(int pixelSize) const {
    return -double(faces_->face->descender) * pixelSize / double(faces_->face->units_per_EM);
}

}  // namespace tstyles
