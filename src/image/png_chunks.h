// Our own walk over a PNG's chunk lengths before libpng sees the file: libpng allocates what a
// chunk's length says before reading it, so a 424-byte PNG whose text chunk claims 1.2 GB made
// it ask for 1.2 GB (found by tests/fuzz, fuzz_style_image).
#pragma once

#include <cstdint>
#include <filesystem>

namespace tstyles {

// For a file that starts with the PNG signature: an InputError naming the chunk unless every
// chunk up to IEND (or the end of the file) lies inside the file's `fileSize` bytes. Files of
// other formats are left alone.
void requirePngChunksInsideFile(const std::filesystem::path& file, std::uint64_t fileSize);

}  // namespace tstyles
