// Image files through OpenImageIO: the format follows the extension (PNG, TIFF, EXR, ...).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "tstyles/core/input_limits.h"
#include "tstyles/image/image.h"

namespace tstyles {

// Writes through a temporary file and a rename. 8-bit formats get rounded, clamped values; float
// formats (EXR) get the floats. Unsupported extensions and write failures are InputErrors naming
// the file.
void writeImage(const Image& image, const std::filesystem::path& file);

// Checks before any work is done that `file` can be written: its folder exists, it is not a
// folder, and OpenImageIO knows its format. InputError naming the file (and the option that named
// it, such as "-o") otherwise.
void requireWritableImagePath(const std::filesystem::path& file, const std::string& option = "");

// Reads any image OpenImageIO knows as RGBA floats with associated alpha (images without alpha
// get alpha 1). InputError naming the file if it cannot be read, or if the pixels its header
// announces would take more than `maxBytes`.
Image readImage(const std::filesystem::path& file, std::uint64_t maxBytes = defaultMemoryCap());

// readImage in a reader process (tstyles/data/isolated_reading.h): a crash or hang inside the image
// libraries becomes an InputError naming the file. For the images a user names (style images).
Image readImageIsolated(const std::filesystem::path& file, std::uint64_t maxBytes = defaultMemoryCap());

// The image resampled to `width` x `height` (OpenImageIO's filtered resize).
Image resizeImage(const Image& image, int width, int height);

}  // namespace tstyles
