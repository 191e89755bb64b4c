// Image and window sizes as users type them: "1920x1080", or "512" for a square where allowed.
#pragma once

#include <optional>
#include <string>

#include <glm/vec2.hpp>

namespace tstyles::cli {

// WIDTHxHEIGHT, two whole numbers of 1 to 5 digits; nullopt where the text is not of that form.
std::optional<glm::ivec2> parseWidthByHeight(const std::string& text);

// "1920x1080": how tables and messages show a size.
std::string widthByHeightText(glm::ivec2 size);

// What `bench --sizes` takes: WIDTHxHEIGHT, or one number for a square, each side in [minimum, maximum];
// anything else is an input error naming the option.
glm::ivec2 parseImageSizeOption(const std::string& text, const std::string& option, int minimum, int maximum);

}  // namespace tstyles::cli
