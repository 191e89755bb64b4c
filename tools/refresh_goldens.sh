#!/usr/bin/env bash
# Re-renders the golden images listed in tests/golden/scenes.txt at 256x256 with build/tstyles.
# Run it only after looking at what changed (the failing test writes actual and difference images
# to build/test-output/), then look at every new image before committing it. See docs/testing.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tstyles="$root/build/tstyles"
[ -x "$tstyles" ] || { echo "refresh_goldens: build first (tools/test.sh or cmake --build build)" >&2; exit 1; }
grep -v '^#' "$root/tests/golden/scenes.txt" | while read -r name; do
  [ -n "$name" ] || continue
  "$tstyles" render "$root/data/scenes/$name.json" -o "$root/tests/golden/$name.png" \
    --width 256 --height 256 --backend "${TSTYLES_BACKEND:-auto}"
done
