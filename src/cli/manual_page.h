// The man page, tstyles.1, written from the CLI's own subcommands and options so that it cannot
// disagree with --help: the build runs the hidden `tstyles manual-page` (docs/install.md).
#pragma once

#include <string>

#include "commands.h"

namespace tstyles::cli {

// The roff text of tstyles(1) for `app` and its visible subcommands.
std::string manualPageRoff(CLI::App& app);

// `tstyles manual-page --output FILE`: hidden from --help, run by the build.
Command addManualPageCommand(CLI::App& app);

}  // namespace tstyles::cli
