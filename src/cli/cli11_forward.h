// CLI11's App, declared for the headers of src/cli/. Only the .cpp files that register options
// include <CLI/CLI.hpp>: CLI11 2.1 is header-only and emits its validators, formatter and config
// reader in every file that includes it (about 20 s of compiling per file under the sanitizers).
#pragma once

namespace CLI {
class App;
}  // namespace CLI
