#!/usr/bin/env bash
# End-to-end: `tstyles info` describes a dataset (time-steps, overlap), and rejects a broken one
# with exit code 2 and one line naming the manifest.
# Usage: info_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

# One overlap row per pair of adjacent time-steps: "0 - 1", "1 - 2", ...
expect_overlap_rows() {
    local steps=$1
    expect_stdout_contains "Overlap of adjacent time-steps"
    local rows
    rows=$(grep -cE '^ +[0-9]+ - [0-9]+ +[0-9.]+ %$' "$OUT_FILE")
    [ "$rows" -eq $((steps - 1)) ] || fail "expected $((steps - 1)) overlap rows, found $rows"
    expect_stdout_contains "$((steps - 2)) - $((steps - 1))"
}

case_default_dataset() {
    local steps
    steps=$(dataset_step_count "$DATASET")
    run_tstyles -- info "$DATASET"
    expect_exit 0
    [ ! -s "$ERR_FILE" ] || fail "info printed on stderr"
    expect_stdout_contains "Time-steps: $steps"
    expect_stdout_contains "Alignment: partial overlap"
    expect_overlap_rows "$steps"
    # The bouncing super-ellipsoid moves, so some adjacent pair overlaps only partly.
    grep -qE '^ +[0-9]+ - [0-9]+ +([0-9]|[1-9][0-9])\.[0-9] %$' "$OUT_FILE" ||
        fail "no adjacent pair of the moving dataset overlaps by less than 100 %"
}

# In the aligned dataset every time-step sits on one grid: every overlap is complete.
case_aligned_dataset() {
    local steps
    steps=$(dataset_step_count "$ALIGNED_DATASET")
    run_tstyles -- info "$ALIGNED_DATASET"
    expect_exit 0
    expect_stdout_contains "Time-steps: $steps"
    expect_stdout_contains "Alignment: fully aligned"
    expect_overlap_rows "$steps"
    local partial
    partial=$(grep -E '^ +[0-9]+ - [0-9]+ ' "$OUT_FILE" | grep -vcE ' 100\.0 %$')
    [ "$partial" -eq 0 ] || fail "$partial adjacent pairs of the aligned dataset do not overlap fully"
}

# The folder names the dataset as well as its manifest does.
case_dataset_folder() {
    run_tstyles -- info "$DATASET"
    expect_exit 0
    cp "$OUT_FILE" "$SCRATCH/from-manifest.txt"
    run_tstyles -- info "$(dirname "$DATASET")"
    expect_exit 0
    diff "$SCRATCH/from-manifest.txt" "$OUT_FILE" >&2 || fail "info on the folder differs from info on the manifest"
}

case_missing_manifest() {
    run_tstyles -- info "$SCRATCH/no-such-dataset/series.json"
    expect_exit 2
    expect_error_line "$SCRATCH/no-such-dataset/series.json" "" "not found"
}

case_corrupt_manifest() {
    mkdir -p "$SCRATCH/dataset"
    head -c 200 "$DATASET" >"$SCRATCH/dataset/series.json"
    run_tstyles -- info "$SCRATCH/dataset/series.json"
    expect_exit 2
    expect_error_line "$SCRATCH/dataset/series.json" "" "not valid JSON"
}

# A typo in a manifest key is named by its path.
case_manifest_unknown_key() {
    mkdir -p "$SCRATCH/dataset"
    sed 's/"placement"/"placment"/' "$DATASET" >"$SCRATCH/dataset/series.json"
    grep -qF '"placment"' "$SCRATCH/dataset/series.json" || fail "the default manifest has no placement to misspell"
    run_tstyles -- info "$SCRATCH/dataset/series.json"
    expect_exit 2
    expect_error_line "$SCRATCH/dataset/series.json" "time_steps[0].placment" "unknown key"
}

run_case
