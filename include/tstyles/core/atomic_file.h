// Writing files so that nothing half-written is ever left behind: write beside the target under a
// temporary name, then rename over it.
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string_view>

namespace tstyles {

// Calls `writeTo(temporaryPath)` and renames the result to `target`. If the writer throws or the
// rename fails, the temporary file is removed and the error propagates (an InputError naming
// `target` for I/O failures).
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& writeTo);

void writeFileAtomically(const std::filesystem::path& target, std::span<const std::byte> bytes);
void writeFileAtomically(const std::filesystem::path& target, std::string_view text);

// The temporary sibling used by writeAtomically: same folder and extension, so that libraries that
// pick a format from the extension (OpenImageIO) still see it.
std::filesystem::path temporarySiblingOf(const std::filesystem::path& target);

}  // namespace tstyles
