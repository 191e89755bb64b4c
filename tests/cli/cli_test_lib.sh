# Shared helpers for the end-to-end tests of the `tstyles` executable: run it, capture what it
# prints, and check exit codes, messages and image files. Sourced by the tests/cli/*_test.sh scripts.
#
# Every script is called as:  bash SCRIPT.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE
# and runs the one function `case_CASE`, in a fresh folder SCRATCH_ROOT/CASE of its own, so ctest
# may run the cases in parallel and a failing case leaves its files behind to look at.

set -u
set -o pipefail

if [ "$#" -ne 4 ] || [ -z "$3" ] || [ -z "$4" ]; then
    echo "usage: $0 TSTYLES SOURCE_DIR SCRATCH_ROOT CASE" >&2
    exit 2
fi
TSTYLES=$1
SOURCE_DIR=$2
SCRATCH="$3/$4"
CASE=$4
# The bundled datasets, generated at build time (the scripts that source this file use them).
DATASET="$SOURCE_DIR/data/superellipsoid/series.json"
# shellcheck disable=SC2034
ALIGNED_DATASET="$SOURCE_DIR/data/superellipsoid-aligned/series.json"
# ctest passes the oiiotool CMake found; by hand, the one on the PATH.
OIIOTOOL=${OIIOTOOL:-oiiotool}

# The bundled dataset's time-step count, from its files rather than from tstyles: one tNN.raw each.
dataset_step_count() {
    find "$(dirname "$1")" -maxdepth 1 -name 't*.raw' ! -name '*_mask.raw' | wc -l | tr -d ' '
}

rm -rf "$SCRATCH"
mkdir -p "$SCRATCH"

# What the last run_tstyles left: exit status, and files holding stdout and stderr.
RC=
OUT_FILE="$SCRATCH/stdout.txt"
ERR_FILE="$SCRATCH/stderr.txt"

fail() {
    echo "FAIL [$CASE]: $*" >&2
    if [ -n "$RC" ]; then
        echo "--- last command exited with $RC; its stdout:" >&2
        cat "$OUT_FILE" >&2
        echo "--- its stderr:" >&2
        cat "$ERR_FILE" >&2
    fi
    exit 1
}

# Runs tstyles with ARGS, in the environment plus the VAR=value settings before the "--":
# run_tstyles [VAR=value...] -- ARGS...
run_tstyles() {
    local environment=()
    while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do
        environment+=("$1")
        shift
    done
    [ "$#" -gt 0 ] && shift
    echo "+ ${environment[*]:+${environment[*]} }tstyles $*" >&2
    RC=0
    env ${environment[@]+"${environment[@]}"} "$TSTYLES" "$@" >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
}

expect_exit() {
    [ "$RC" = "$1" ] || fail "expected exit code $1, got $RC"
}

expect_stdout_contains() {
    grep -qF -- "$1" "$OUT_FILE" || fail "stdout does not contain '$1'"
}

expect_stderr_contains() {
    grep -qF -- "$1" "$ERR_FILE" || fail "stderr does not contain '$1'"
}

# A user error is one line, "tstyles: <file>: <field>: <problem>", naming the file (and the field
# when there is one): expect_error_line FILE [FIELD] [PROBLEM_TEXT].
expect_error_line() {
    local file=$1 field=${2:-} problem=${3:-}
    local lines
    lines=$(wc -l <"$ERR_FILE")
    [ "$lines" -eq 1 ] || fail "expected exactly one line on stderr, got $lines"
    local prefix="tstyles: $file: "
    [ -n "$field" ] && prefix="tstyles: $file: $field: "
    case "$(cat "$ERR_FILE")" in
        "$prefix"*) ;;
        *) fail "stderr does not start with '$prefix'" ;;
    esac
    [ -z "$problem" ] || expect_stderr_contains "$problem"
}

# Nothing was written: neither the file nor a temporary sibling (".NAME.tmpPID.EXT").
expect_no_output() {
    local file=$1
    [ ! -e "$file" ] || fail "$file exists, but the command failed and should not have written it"
    local folder
    folder=$(dirname "$file")
    if [ -d "$folder" ]; then
        local leftovers
        leftovers=$(find "$folder" -maxdepth 1 -name '.*.tmp*')
        [ -z "$leftovers" ] || fail "temporary files left behind: $leftovers"
    fi
}

# An image file that OpenImageIO reads, of the given size, with 4 channels, and not one colour all
# over: expect_image FILE WIDTH HEIGHT.
expect_image() {
    local file=$1 width=$2 height=$3
    [ -f "$file" ] || fail "$file was not written"
    local info
    info=$("$OIIOTOOL" --info "$file" 2>&1) || fail "oiiotool cannot read $file: $info"
    # oiiotool pads the sizes: "out.png :   64 x   64, 4 channel, uint8 png".
    echo "$info" | grep -qE ": +$width x +$height, 4 channel" ||
        fail "$file is not a $width x $height RGBA image: $info"
    local leftovers
    leftovers=$(find "$(dirname "$file")" -maxdepth 1 -name '.*.tmp*')
    [ -z "$leftovers" ] || fail "temporary files left behind: $leftovers"
    # The stats list min and max per channel; an image of one colour has min == max in R, G and B.
    local stats
    stats=$("$OIIOTOOL" --stats "$file" 2>&1) || fail "oiiotool --stats failed on $file: $stats"
    local minimum maximum
    minimum=$(echo "$stats" | awk '/Stats Min:/ {print $3, $4, $5; exit}')
    maximum=$(echo "$stats" | awk '/Stats Max:/ {print $3, $4, $5; exit}')
    if [ -z "$minimum" ] || [ -z "$maximum" ]; then fail "no min/max in the stats of $file: $stats"; fi
    [ "$minimum" != "$maximum" ] || fail "$file is one colour all over (RGB min = max = $minimum)"
}

# Whether the window can be tried here: without xvfb-run the case says SKIP and this returns 1.
have_xvfb() {
    command -v xvfb-run >/dev/null && return 0
    echo "SKIP [$CASE]: xvfb-run not found (package xvfb)"
    return 1
}

# Opens the window on a dataset under Xvfb, waits for the refined picture, saves the scene to
# $SCRATCH/saved.json and a screenshot to $SCRATCH/shot.png, and quits; then expects exit 0 and the
# screenshot as an image of the size the viewer says it wrote (the view beside the panels: the
# layout, not --size, decides it): view_and_screenshot DATASET [VIEW_OPTIONS...].
view_and_screenshot() {
    printf 'wait-refined\nsave-scene ${OUT}/saved.json\nscreenshot ${OUT}/shot.png\nquit\n' >"$SCRATCH/script.txt"
    RC=0
    OUT="$SCRATCH" timeout 120 xvfb-run -a -s "-screen 0 1024x768x24" "$TSTYLES" view "$@" --no-vsync \
        --script "$SCRATCH/script.txt" >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
    expect_exit 0
    local size
    size=$(sed -n 's/^wrote screenshot .* (\([0-9]*\)x\([0-9]*\))$/\1 \2/p' "$OUT_FILE")
    [ -n "$size" ] || fail "the viewer did not say it wrote the screenshot"
    # shellcheck disable=SC2086
    expect_image "$SCRATCH/shot.png" $size
}

# A scene of 64x64 pixels on the given dataset (default: the bundled one), with extra top-level
# keys appended verbatim: write_scene FILE [DATASET] [EXTRA_JSON_MEMBERS].
write_scene() {
    local file=$1 dataset=${2:-$DATASET} extra=${3:-}
    {
        echo "{"
        echo "  // Written by $CASE."
        echo "  \"dataset\": \"$dataset\","
        echo "  \"image\": {\"width\": 64, \"height\": 64}${extra:+,}"
        [ -z "$extra" ] || echo "  $extra"
        echo "}"
    } >"$file"
}

run_case() {
    if ! declare -F "case_$CASE" >/dev/null; then
        echo "unknown case '$CASE' in $0" >&2
        exit 2
    fi
    [ -x "$TSTYLES" ] || fail "no executable at $TSTYLES"
    "case_$CASE"
    echo "PASS [$CASE]"
}

# The table of a `tstyles check` run's stdout, in suite order (after the progress lines and a blank
# line; the summary line, which names the report folder, left out) without its timings.
table_of() {
    sed -n '/^$/,$p' "$1" | sed '$d' | sed -E 's/  \([0-9.]+ s\)$//'
}

# junit.xml without its time="..." attributes: timings differ from run to run, the rest must not.
junit_without_times() {
    sed -E 's/ time="[^"]*"//g' "$1"
}
