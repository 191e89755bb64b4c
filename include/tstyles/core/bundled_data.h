// Where the bundled data lives (scenes, generated datasets, built-in styles).
#pragma once

#include <filesystem>

namespace tstyles {

// TSTYLES_DATA_DIR if set, else the data/ folder of the source tree this binary was built from.
std::filesystem::path bundledDataDirectory();

}  // namespace tstyles
