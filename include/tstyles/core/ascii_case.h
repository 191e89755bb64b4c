// ASCII lower case, the one helper for the names the program compares without case: file
// extensions, CF attribute values, units, NRRD spaces. Bytes outside ASCII (UTF-8 "µm") stay as
// they are.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace tstyles {

std::string asciiLowercase(std::string_view text);
// ".NII" of "BRAIN.NII" -> ".nii"; "" without an extension.
std::string lowercaseExtension(const std::filesystem::path& file);
// "Series.JSON" of "/a/Series.JSON" -> "series.json".
std::string lowercaseFileName(const std::filesystem::path& file);

}  // namespace tstyles
