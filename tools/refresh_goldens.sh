#!/usr/bin/env bash
# Re-renders golden images of the project's suite (tests/golden/suite.json) with build/tstyles:
# the cases named (comma-separated), or all of them. Run it only after looking at what changed (the
# failing check writes expected, actual and difference images and an HTML page to
# build/test-output/check-*/), then look at every new image before committing it. docs/testing.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tstyles="$root/build/tstyles"
[ -x "$tstyles" ] || { echo "refresh_goldens: build first (tools/test.sh or cmake --build build)" >&2; exit 1; }
if [ "$#" -gt 0 ]; then
  "$tstyles" check "$root/tests/golden/suite.json" --update "$1" --report "$root/build/test-output/check-refresh" \
    --backend "${TSTYLES_BACKEND:-auto}"
else
  "$tstyles" check "$root/tests/golden/suite.json" --update --all --report "$root/build/test-output/check-refresh" \
    --backend "${TSTYLES_BACKEND:-auto}"
fi
