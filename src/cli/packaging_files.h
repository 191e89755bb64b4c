// The desktop entry, the MIME package and the package description, written from the format table
// (tstyles/data/format_listing.h) by the hidden `tstyles packaging-file KIND --output FILE`, which
// the build runs (tools/cmake/Install.cmake), as it runs `tstyles manual-page`.
#pragma once

#include "commands.h"

namespace tstyles::cli {

Command addPackagingFileCommand(CLI::App& app);

}  // namespace tstyles::cli
