// Recognising a file by its first bytes, in one place: the format table's sniffers (NetCDF, NRRD,
// TIFF, DICOM, VTK XML) read the file's start here and compare it with their magic. A file that
// cannot be read, or is shorter than the magic, is not the format.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace tstyles {

// Up to `count` bytes from the file's start (fewer where the file is shorter; none where it cannot
// be opened).
std::string fileStart(const std::filesystem::path& file, std::size_t count);

// Whether `start` holds `magic` at `offset`.
bool hasMagicAt(std::string_view start, std::size_t offset, std::string_view magic);

}  // namespace tstyles
