#!/usr/bin/env bash
# Draws the application icon (tools/packaging/icons/tstyles-{48,128,256}.png) with our own tools: the
# bundled Figure 1 scene with lit-sphere styles rendered by `tstyles render` on a transparent
# background, trimmed to the object and fitted into squares by oiiotool. The icons are committed,
# so that a build needs no OpenGL; run this after a change to the scene or the renderer:
#   tools/packaging/make_icons.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The scene as bundled, its dataset made absolute and its background transparent.
sed -e "s|\"dataset\": \"../superellipsoid/series.json\"|\"dataset\": \"$root/data/superellipsoid/series.json\"|" \
    -e 's|"background": \[1.0, 1.0, 1.0, 1.0\]|"background": [1.0, 1.0, 1.0, 0.0]|' \
    "$root/data/scenes/figure1-styled-focus-step3.json" >"$work/icon-scene.json"
grep -q '"background": \[1.0, 1.0, 1.0, 0.0\]' "$work/icon-scene.json" || {
    echo "make_icons: the scene's background line changed; update the sed above" >&2
    exit 1
}
"$build/tstyles" render "$work/icon-scene.json" -o "$work/render.png" --width 768 --height 768
for size in 256 128 48; do
    oiiotool "$work/render.png" --autotrim --fit:pad=1:filter=lanczos3 "${size}x${size}" \
        -d uint8 -o "$root/tools/packaging/icons/tstyles-$size.png"
done
echo "wrote tools/packaging/icons/tstyles-{256,128,48}.png"
