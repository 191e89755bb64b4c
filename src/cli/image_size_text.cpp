#include "image_size_text.h"

#include "tstyles/core/errors.h"

namespace tstyles::cli {
namespace {

bool isWholeNumber(const std::string& text) {
    return !text.empty() && text.size() <= 5 && text.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

std::optional<glm::ivec2> parseWidthByHeight(const std::string& text) {
    const auto x = text.find('x');
    if (x == std::string::npos || !isWholeNumber(text.substr(0, x)) || !isWholeNumber(text.substr(x + 1)))
        return std::nullopt;
    return glm::ivec2{std::stoi(text.substr(0, x)), std::stoi(text.substr(x + 1))};
}

std::string widthByHeightText(glm::ivec2 size) { return std::to_string(size.x) + "x" + std::to_string(size.y); }

glm::ivec2 parseImageSizeOption(const std::string& text, const std::string& option, int minimum, int maximum) {
    std::optional<glm::ivec2> size = parseWidthByHeight(text);
    if (!size && isWholeNumber(text)) size = glm::ivec2{std::stoi(text)};
    if (!size)
        throwInputError("", option, "expected WIDTHxHEIGHT such as 1920x1080, or one number for a square, got \"" + text + "\"");
    if (size->x < minimum || size->y < minimum || size->x > maximum || size->y > maximum)
        throwInputError("", option, "each side must be between " + std::to_string(minimum) + " and " +
                                        std::to_string(maximum) + " pixels, got \"" + text + "\"");
    return *size;
}

}  // namespace tstyles::cli
