#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test through ctest (render tests under both
# headless backends, viewer tests under Xvfb).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install_dependencies.sh"
"$root/tools/build.sh"
cd "$root/build"
ctest --output-on-failure -j "$(nproc)"
