#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: install what is missing, build, and render the gallery
# of bundled scenes (the paper's figures on the default dataset) headless into out/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install_dependencies.sh"
"$root/tools/build.sh"
"$root/tools/render_gallery.sh" "$root/out"
