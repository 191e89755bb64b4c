#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: install what is missing, build, then open the viewer on
# the bundled default scene (the paper's Figure 1 on the bouncing super-ellipsoid). Without a display
# it renders the gallery of bundled scenes headless into out/ instead and says so.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install_dependencies.sh"
"$root/tools/build.sh"
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  exec "$root/build/tstyles" view
fi
echo "run.sh: no display, so rendering the gallery headless (for the window: xvfb-run -a build/tstyles view, or run on a desktop)"
"$root/tools/render_gallery.sh" "$root/out"
