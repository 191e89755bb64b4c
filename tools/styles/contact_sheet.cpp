// Laying the style pictures out on one opaque sheet.
#include "contact_sheet.h"

#include <algorithm>
#include <cmath>

namespace styles {

namespace {

constexpr int kGap = 4;
constexpr std::uint8_t kBackground = 250;
constexpr std::uint8_t kCheckerDark = 96;
constexpr std::uint8_t kCheckerLight = 160;

// Style-over-checkerboard for one cell whose top-left corner is at (left, top) on the sheet.
void pasteOverChecker(const RgbaImage& sphere, RgbaImage& sheet, int left, int top) {
    const int square = std::max(1, sphere.width / 8);
    for (int y = 0; y < sphere.height; ++y)
        for (int x = 0; x < sphere.width; ++x) {
            const std::uint8_t* in =
                &sphere.rgba[(std::size_t(y) * std::size_t(sphere.width) + std::size_t(x)) * 4];
            std::uint8_t* out =
                &sheet.rgba[(std::size_t(top + y) * std::size_t(sheet.width) + std::size_t(left + x)) * 4];
            const double checker = ((x / square + y / square) % 2 == 0) ? kCheckerLight : kCheckerDark;
            const double alpha = in[3] / 255.0;
            for (int c = 0; c < 3; ++c)
                out[c] = static_cast<std::uint8_t>(std::lround(in[c] * alpha + checker * (1.0 - alpha)));
            out[3] = 255;
        }
}

}  // namespace

RgbaImage drawContactSheet(const std::vector<StyleDefinition>& styles, int cellSize, int columns) {
    const int count = static_cast<int>(styles.size());
    const int rows = (count + columns - 1) / columns;
    RgbaImage sheet{kGap + columns * (cellSize + kGap), kGap + rows * (cellSize + kGap), {}};
    sheet.rgba.assign(std::size_t(sheet.width) * std::size_t(sheet.height) * 4, kBackground);
    for (int index = 0; index < count; ++index) {
        const RgbaImage sphere =
            rasterizeLitSphere(styles[std::size_t(index)], cellSize, OutsideDisc::Transparent);
        pasteOverChecker(sphere, sheet, kGap + (index % columns) * (cellSize + kGap),
                         kGap + (index / columns) * (cellSize + kGap));
    }
    return sheet;
}

}  // namespace styles
