#!/usr/bin/env bash
# Does the test suite catch small regressions? Applies one small mutant at a time to a copy of the
# shaders (read at run time through TSTYLES_SHADER_DIR, so nothing is rebuilt) and runs the render
# and golden tests of a built tree with it; a mutant is caught when a test fails. docs/testing.md,
# "Mutation check", lists the mutants and what caught them.
# Usage: tools/mutation_check.sh [BUILD_DIR] [MUTANT ...]   (default: build, every mutant)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
shift || true
# The tests that render through the shaders: the golden suite first (quick), then the render tests
# and the CLI's image cases. A caught mutant stops at its first failing test.
tests='^(check\.goldens|egl\.|osmesa\.|cli\.(render|compositors|structured)\.)'

# name|file under shaders/|python replacement (old, new): each mutant changes one thing.
mutants=(
    # A few dozen pixels brightened by 51/255: every 37th pixel of every 37th row.
    "brightened_pixels|raycast.frag|fragmentColor = accumulated + (1.0 - accumulated.a) * premultipliedBackground;|fragmentColor = accumulated + (1.0 - accumulated.a) * premultipliedBackground; if (int(gl_FragCoord.x) % 37 == 0 && int(gl_FragCoord.y) % 37 == 0) fragmentColor.rgb = min(fragmentColor.rgb + 0.2, vec3(1.0));"
    # Time of maximum: a tie goes to the later time-step.
    "tie_rule_flipped|tc_time_of_maximum.glsl|(s.density == state.highest.density && s.step < state.highest.step)|(s.density == state.highest.density && s.step > state.highest.step)"
    # Time-step 1 sampled a hundredth of a voxel off along x.
    "placement_nudged|volume_sampling.glsl|vec3 voxel = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz;|vec3 voxel = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz + (step == 1 ? vec3(0.01, 0.0, 0.0) : vec3(0.0));"
    # The STF table read one entry off.
    "stf_table_one_off|transfer_functions.glsl|(clamp(x, 0.0, 1.0) * (transferTableSize - 1.0) + 0.5) / transferTableSize|(clamp(x, 0.0, 1.0) * (transferTableSize - 1.0) + 1.5) / transferTableSize"
)

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
caught=()
survived=()
for mutant in "${mutants[@]}"; do
    IFS='|' read -r name file old new <<<"$mutant"
    if [ $# -gt 0 ] && [[ " $* " != *" $name "* ]]; then continue; fi
    rm -rf "$scratch/shaders" && cp -r "$root/shaders" "$scratch/shaders"
    OLD="$old" NEW="$new" FILE="$scratch/shaders/$file" python3 - <<'PY'
import os, sys
path, old, new = os.environ["FILE"], os.environ["OLD"], os.environ["NEW"]
text = open(path).read()
if text.count(old) != 1:
    sys.exit(f"mutation_check: {path}: the text to mutate occurs {text.count(old)} times, not once: {old}")
open(path, "w").write(text.replace(old, new))
PY
    echo "== mutant $name ($file)"
    log="$scratch/$name.log"
    start=$SECONDS
    if (cd "$build" && TSTYLES_SHADER_DIR="$scratch/shaders" ctest -R "$tests" -j "$(nproc)" --stop-on-failure \
            >"$log" 2>&1); then
        survived+=("$name")
        echo "   SURVIVED: every test passed ($((SECONDS - start)) s)"
    else
        caught+=("$name")
        echo "   caught ($((SECONDS - start)) s) by: $(grep -E '^\s+[0-9]+ - ' "$log" | sed -E 's/^\s+[0-9]+ - //; s/ \(.*//' | head -3 | tr '\n' ' ')"
    fi
done
echo
echo "caught: ${caught[*]:-none}"
echo "survived: ${survived[*]:-none}"
[ ${#survived[@]} -eq 0 ]
