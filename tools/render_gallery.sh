#!/usr/bin/env bash
# Renders every scene in data/scenes/ headless with build/tstyles into the given folder (default out/).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
output=${1:-"$root/out"}
size=${GALLERY_SIZE:-512}
mkdir -p "$output"
for scene in "$root"/data/scenes/*.json; do
  name=$(basename "$scene" .json)
  "$root/build/tstyles" render "$scene" -o "$output/$name.png" --width "$size" --height "$size" >/dev/null
  echo "rendered $output/$name.png"
done
echo "gallery: $(ls "$output"/*.png | wc -l) images in $output"
