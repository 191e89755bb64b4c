// Location of the bundled data folder.
#include "tstyles/core/bundled_data.h"

#include <cstdlib>

namespace tstyles {

std::filesystem::path bundledDataDirectory() {
    if (const char* directory = std::getenv("TSTYLES_DATA_DIR"); directory != nullptr && *directory != 0)
        return directory;
    return TSTYLES_BUNDLED_DATA_DIR;
}

}  // namespace tstyles
