#!/usr/bin/env bash
# End-to-end: `tstyles bench` on tiny images: the matrix skips a dataset folder that is not there
# with a note, the scaling run generates longer super-ellipsoid series and reports each n, and
# --json writes the same cases.
# Usage: bench_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

# Rows of the table: "<dataset> <compositor> <n> <size> ..." for the three compositors.
expect_rows() {
    local dataset=$1 steps=$2 size=$3
    for compositor in temporal-mip temporal-average temporal-max-change; do
        grep -qE "^$dataset +$compositor +$steps +$size " "$OUT_FILE" ||
            fail "no row for $dataset, $compositor, n = $steps, size $size"
    done
}

case_matrix_skips_missing_dataset() {
    run_tstyles -- bench --sizes 24 --frames 1 --warmup 0 --datasets superellipsoid no-such-dataset
    expect_exit 0
    expect_stderr_contains "note: skipping dataset no-such-dataset"
    expect_rows superellipsoid 10 24x24
    grep -q "no-such-dataset" "$OUT_FILE" && fail "the missing dataset has a row"
    return 0
}

# The synthetic hurricane (generated with the build) measures with its own Figure 5 and 6 scenes.
case_hurricane_rows() {
    run_tstyles -- bench --sizes 24 --frames 1 --warmup 0 --datasets hurricane --json "$SCRATCH/hurricane.json"
    expect_exit 0
    expect_rows hurricane 10 24x24
    grep -q '"scene": "figure5-focus-step5"' "$SCRATCH/hurricane.json" || fail "MIP and average not on Figure 5's scene"
    grep -q '"scene": "figure6-left-max-density-change"' "$SCRATCH/hurricane.json" ||
        fail "max density change not on Figure 6's scene"
}

case_no_dataset_there() {
    run_tstyles -- bench --sizes 24 --frames 1 --warmup 0 --datasets no-such-dataset
    expect_exit 2
    expect_stderr_contains "none of the datasets is there"
}

case_scaling_json() {
    run_tstyles -- bench --scaling 12 --sizes 24 --frames 1 --warmup 0 --json "$SCRATCH/scaling.json"
    expect_exit 0
    expect_rows superellipsoid-x12 12 24x24
    expect_rows superellipsoid-aligned-x12 12 24x24
    [ -s "$SCRATCH/scaling.json" ] || fail "no JSON written"
    local cases
    cases=$(grep -c '"time_steps": 12' "$SCRATCH/scaling.json")
    [ "$cases" -eq 6 ] || fail "expected 6 cases of 12 time-steps in the JSON, found $cases"
}

# --max-gpu-memory: the series is stored within it as `render` stores it, said on stderr, and
# the JSON says what changed for each case; a bad size is refused before anything is read.
case_max_gpu_memory() {
    run_tstyles -- bench --sizes 24 --frames 1 --warmup 0 --datasets superellipsoid --max-gpu-memory 2M \
        --json "$SCRATCH/budget.json"
    expect_exit 0
    expect_rows superellipsoid 10 24x24
    expect_stderr_contains "GPU memory budget 2.0 MiB (--max-gpu-memory)"
    local changed
    changed=$(grep -c '"resolution 1/' "$SCRATCH/budget.json")
    [ "$changed" -eq 3 ] || fail "expected 3 cases stored coarser in the JSON, found $changed"
    run_tstyles -- bench --sizes 24 --frames 1 --warmup 0 --datasets superellipsoid --max-gpu-memory lots
    expect_exit 2
    expect_stderr_contains "--max-gpu-memory"
}

# A size may be WIDTHxHEIGHT (1920x1080 for the GPU figures) beside a plain number for a square;
# the JSON gives each case's width and height; a size outside 16..8192 or of another form is refused.
case_wide_size() {
    run_tstyles -- bench --sizes 48x24 32 --frames 1 --warmup 0 --datasets superellipsoid --json "$SCRATCH/wide.json"
    expect_exit 0
    expect_rows superellipsoid 10 48x24
    expect_rows superellipsoid 10 32x32
    local wide high
    wide=$(grep -cE '"width": 48,?$' "$SCRATCH/wide.json")
    high=$(grep -cE '"height": 24,?$' "$SCRATCH/wide.json")
    [ "$wide" -eq 3 ] && [ "$high" -eq 3 ] ||
        fail "expected 3 cases 48 wide and 24 high in the JSON, found $wide and $high"
    run_tstyles -- bench --sizes 48x9000 --frames 1 --warmup 0 --datasets superellipsoid
    expect_exit 2
    expect_stderr_contains "--sizes"
    expect_stderr_contains "between 16 and 8192"
    run_tstyles -- bench --sizes 48by24 --frames 1 --warmup 0 --datasets superellipsoid
    expect_exit 2
    expect_stderr_contains "expected WIDTHxHEIGHT"
}

# --stages: a second table of each case's passes and parts (entry/exit, raycasting, its ray setup,
# march and sampling), the same in the JSON; --distributed does not take it.
case_stages() {
    run_tstyles -- bench --sizes 24 --frames 1 --warmup 0 --datasets superellipsoid --stages \
        --json "$SCRATCH/stages.json"
    expect_exit 0
    expect_rows superellipsoid 10 24x24
    grep -q "^ms per pass and part" "$OUT_FILE" || fail "no table of passes and parts"
    grep -qE "^dataset +compositor +size +entry/exit +raycast +ray setup +march +sampling +march alone +march samples" \
        "$OUT_FILE" || fail "the stage table's header differs"
    local stage_rows
    stage_rows=$(grep -cE "^superellipsoid +temporal-[a-z-]+ +24x24( +-?[0-9]+\.[0-9]){6} +[0-9]+$" "$OUT_FILE")
    [ "$stage_rows" -eq 3 ] || fail "expected 3 stage rows, found $stage_rows"
    local in_json
    in_json=$(grep -c '"stages_gpu_ms"' "$SCRATCH/stages.json")
    [ "$in_json" -eq 3 ] || fail "expected 3 cases with stages in the JSON, found $in_json"
    for key in entry_exit raycast ray_setup march sampling march_alone march_alone_samples; do
        grep -q "\"$key\":" "$SCRATCH/stages.json" || fail "no $key in the JSON's stages"
    done
    run_tstyles -- bench --distributed --stages --sizes 24 --frames 1 --warmup 0
    expect_exit 2
    expect_stderr_contains "--stages"
}

# Issue 52: `bench FILE` times the automatic scene of a dataset (any format render reads), as
# `render FILE` draws it; `--automatic` adds the bundled datasets' automatic scenes after the matrix;
# a scene file is timed as written.
case_automatic_scene_of_a_file() {
    run_tstyles -- bench "$DATASET" --sizes 24 --frames 1 --warmup 0 --json "$SCRATCH/file.json"
    expect_exit 0
    expect_stdout_contains "scenes: each dataset's automatic scene"
    grep -qE "^series.json +temporal-mip +10 +24x24 " "$OUT_FILE" || fail "no row for the file's automatic scene"
    grep -q '"scene": "automatic"' "$SCRATCH/file.json" || fail "the JSON does not say the scene is the automatic one"
    run_tstyles -- bench "$SOURCE_DIR/data/scenes/figure4-temporal-mip.json" --sizes 24 --frames 1 --warmup 0 \
        --json "$SCRATCH/scene.json"
    expect_exit 0
    grep -qE "^figure4-temporal-mip.json +temporal-mip +10 +24x24 " "$OUT_FILE" || fail "no row for the scene file"
    grep -q '"scene": "scene file"' "$SCRATCH/scene.json" || fail "the JSON does not say the scene is the file's"
    run_tstyles -- bench "$DATASET" --styled --sizes 24 --frames 1 --warmup 0
    expect_exit 2
    expect_stderr_contains "FILE: times the files' own scenes"
}

case_automatic_after_the_matrix() {
    run_tstyles -- bench --automatic --datasets superellipsoid --sizes 24 --frames 1 --warmup 0
    expect_exit 0
    expect_rows superellipsoid 10 24x24
    grep -qE "^superellipsoid \(automatic\) +temporal-mip +10 +24x24 " "$OUT_FILE" ||
        fail "no row for the bundled dataset's automatic scene"
}

run_case
