#!/usr/bin/env bash
# Renders docs/gallery/compositors/ (docs/compositors.md): one picture per temporal compositor with
# build/tstyles, each on a bundled scene chosen for what the compositor shows. Needs the bundled
# data (a build generates it). Usage: tools/render_compositor_gallery.sh [OUTPUT_FOLDER]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tstyles=${TSTYLES:-"$root/build/tstyles"}
output=${1:-"$root/docs/gallery/compositors"}
size=${GALLERY_SIZE:-384}
scenes="$root/data/scenes"
mkdir -p "$output"

# render SCENE_FILE COMPOSITOR: OUTPUT/COMPOSITOR.png, the scene with --tc COMPOSITOR.
render() {
  "$tstyles" render "$1" --tc "$2" --width "$size" --height "$size" -o "$output/$2.png" >/dev/null
  echo "rendered $output/$2.png"
}

# Time-steps picked or styled by the index TSTF, on the hurricane (every time-step on one grid).
# The scene's threshold (0.3) is first-arrival's, last-above's and threshold-crossing's (rising).
for compositor in temporal-mip time-of-max first-arrival last-above threshold-crossing temporal-average chronovolume; do
  render "$scenes/compositors-hurricane-index.json" "$compositor"
done
# The minimum needs every time-step dense at a place: the moving storm leaves none, the bouncing
# super-ellipsoid (each time-step on its own grid, missing values elsewhere) shows what persists.
render "$scenes/figure4-temporal-mip.json" temporal-min
# Unsigned values through a sequential gradient TSTF, signed ones through a diverging one.
for compositor in temporal-max-change temporal-std-dev; do
  render "$scenes/compositors-hurricane-spread.json" "$compositor"
done
for compositor in linear-trend difference; do
  render "$scenes/compositors-hurricane-signed.json" "$compositor"
done
# The scene's own code: examples/compositors/time-of-peak.glsl.
"$tstyles" render "$root/examples/compositors/time-of-peak.json" --width "$size" --height "$size" \
  -o "$output/custom-time-of-peak.png" >/dev/null
echo "rendered $output/custom-time-of-peak.png"
