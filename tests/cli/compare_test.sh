#!/usr/bin/env bash
# End-to-end: `tstyles compare` on images made with oiiotool: exit 0 within the thresholds, 1 beyond
# (with the heat map and side-by-side written), 2 for bad input naming the file.
# Usage: compare_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

make_flat() {  # make_flat FILE WIDTH HEIGHT R,G,B
    "$OIIOTOOL" --pattern "constant:color=$4" "$2x$3" 3 -d uint8 -o "$1" || fail "oiiotool could not make $1"
}

case_identical() {
    make_flat "$SCRATCH/a.png" 32 32 0.2,0.4,0.6
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/a.png"
    expect_exit 0
    expect_stdout_contains "max difference   0/255"
    expect_stdout_contains "SSIM             1 "
    expect_stdout_contains "within the thresholds"
}

case_beyond_writes_pictures() {
    make_flat "$SCRATCH/a.png" 32 32 0.2,0.4,0.6
    # The same with a 16x16 square changed in green by 26/255.
    "$OIIOTOOL" "$SCRATCH/a.png" --fill:color=0.2,0.5,0.6 16x16+8+8 -d uint8 -o "$SCRATCH/b.png" || fail "oiiotool --fill"
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/b.png" --diff "$SCRATCH/diff.png" --side-by-side "$SCRATCH/sbs.png"
    expect_exit 1
    expect_stdout_contains "BEYOND: max delta 26/255 > 2/255"
    # The first of the changed square in row order, with both values as the files store them.
    expect_stdout_contains "                8     8    26   51 102 153 255    51 128 153 255"
    expect_image "$SCRATCH/diff.png" 32 32
    expect_image "$SCRATCH/sbs.png" 104 32
    # Loosened on the command line, the same pair passes.
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/b.png" --max-difference 30 --max-failing-share 100 --max-mean 30 \
        --min-ssim 0
    expect_exit 0
}

case_thresholds_file() {
    make_flat "$SCRATCH/a.png" 16 16 0.2,0.4,0.6
    make_flat "$SCRATCH/b.png" 16 16 0.2,0.41,0.6
    echo '{"max_difference": 3, "max_failing_share": 100, "max_mean": 1}' >"$SCRATCH/loose.json"
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/b.png" --thresholds "$SCRATCH/loose.json"
    expect_exit 0
    echo '{"max_difference": 3, "tolerance": 2}' >"$SCRATCH/bad.json"
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/b.png" --thresholds "$SCRATCH/bad.json"
    expect_exit 2
    expect_stderr_contains "$SCRATCH/bad.json: tolerance: unknown key"
    # Differences are whole 1/255 steps: 2.5 is refused rather than read as 2.
    echo '{"max_difference": 2.5}' >"$SCRATCH/fraction.json"
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/b.png" --thresholds "$SCRATCH/fraction.json"
    expect_exit 2
    expect_stderr_contains "$SCRATCH/fraction.json: max_difference: must be a whole number"
    echo '{"min_ssim": 1.5}' >"$SCRATCH/ssim.json"
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/b.png" --thresholds "$SCRATCH/ssim.json"
    expect_exit 2
    expect_stderr_contains "$SCRATCH/ssim.json: min_ssim: must be <= 1"
}

case_option_out_of_range() {
    make_flat "$SCRATCH/a.png" 16 16 0.2,0.4,0.6
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/a.png" --max-difference -1
    expect_exit 2
    expect_stderr_contains "--max-difference"
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/a.png" --min-ssim 1.5
    expect_exit 2
    expect_stderr_contains "--min-ssim"
}

case_different_sizes() {
    make_flat "$SCRATCH/a.png" 32 32 0.2,0.4,0.6
    make_flat "$SCRATCH/b.png" 32 16 0.2,0.4,0.6
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/b.png"
    expect_exit 2
    expect_stderr_contains "$SCRATCH/b.png: is 32x16 but $SCRATCH/a.png is 32x32"
}

case_missing_file() {
    make_flat "$SCRATCH/a.png" 32 32 0.2,0.4,0.6
    run_tstyles -- compare "$SCRATCH/a.png" "$SCRATCH/nothing.png"
    expect_exit 2
    expect_stderr_contains "nothing.png"
}

run_case
