#!/usr/bin/env bash
# Renders the pictures of docs/automatic-scene.md and the maps of docs/ray-modes.md: the realistic
# files of tests/data/realistic_datasets.h, written afresh, each through the automatic scene
# (`tstyles render FILE`, no scene file) with build/tstyles. The first table's "before" pictures
# (the plain defaults before the automatic scene existed) are history and are not re-rendered.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tstyles="$root/build/tstyles"
automatic="$root/docs/gallery/automatic"
rays="$root/docs/gallery/ray-modes"
files=$(mktemp -d)
trap 'rm -rf "$files"' EXIT
"$root/build/tests/write_realistic_datasets" "$files" >/dev/null

render() {  # FILE OUTPUT SIZE [OPTION...]
  local file=$1 output=$2 size=$3
  shift 3
  "$tstyles" render "$files/$file" -o "$output" --width "$size" --height "$size" "$@" >/dev/null
  echo "rendered $output"
}

# The first table: the automatic scene alone, no annotations.
render ocean-eddy.nc "$automatic/ocean-eddy-after.png" 320
render moving-blob.nii "$automatic/moving-blob-after.png" 320
render ct-phantom.nii "$automatic/ct-phantom-after.png" 320
render mr-slab.nii "$automatic/mr-slab-after.png" 512 --annotate
# The five shapes of issue 40: --unchanged off before, the automatic scene after, annotated.
for name in woa-climatology.nc forecast.nc fmri-run.nii brain-follow-up.nii ct-head-perfusion.nii; do
  stem=${name%.*}
  render "$name" "$automatic/$stem-before.png" 480 --annotate --unchanged off
  render "$name" "$automatic/$stem-after.png" 480 --annotate
done
# Maps as the largest change along each column, and composited as they were until 7 December.
for name in woa-climatology.nc forecast.nc; do
  stem=${name%.*}
  render "$name" "$rays/$stem-composite.png" 320 --ray composite
  render "$name" "$rays/$stem-largest-change.png" 320
done
