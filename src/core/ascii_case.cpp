// ASCII lower case (ascii_case.h).
#include "tstyles/core/ascii_case.h"

namespace tstyles {

std::string asciiLowercase(std::string_view text) {
    std::string lower(text);
    for (char& c : lower)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return lower;
}

std::string lowercaseExtension(const std::filesystem::path& file) { return asciiLowercase(file.extension().string()); }

std::string lowercaseFileName(const std::filesystem::path& file) { return asciiLowercase(file.filename().string()); }

}  // namespace tstyles
