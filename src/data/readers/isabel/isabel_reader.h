// The IEEE Visualization 2004 contest's Hurricane Isabel files: one file per hour and variable
// (QCLOUDf01.bin ... QCLOUDf48.bin, optionally gzip-compressed), each 500 x 500 x 100 big-endian
// float32 values, x fastest, land and below-ground marked by 1.0e35 (read as missing).
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "../source_series.h"

namespace tstyles {

// True when the name looks like an Isabel file: letters, 'f', the hour, ".bin" or ".bin.gz".
bool isIsabelFileName(const std::filesystem::path& file);

// The files of one variable, in any order: they are sorted by hour, and the hour is the time.
// `dims` replaces 500 x 500 x 100 (for files cut down in the same layout).
SourceSeries openIsabel(const std::vector<std::filesystem::path>& files, const std::optional<glm::ivec3>& dims);

}  // namespace tstyles
