#!/usr/bin/env bash
# End-to-end: `mpirun -np N tstyles render ... --distributed` (sort-last over MPI processes,
# docs/scaling.md): the image matches one process, and a failure on one process or on all ends
# every process with one message and exit 2 (never a hang: ctest's timeout would show one).
# `check --distributed` (a suite's cases spread over the processes): the same table, report,
# goldens and exit code as one process, and bad suites or cases end every process.
# Usage: distributed_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh); MPIEXEC is
# mpirun, with OMPI_ALLOW_RUN_AS_ROOT set by ctest where the tests run as root.
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"
MPIEXEC=${MPIEXEC:-mpirun}

# run_mpi N ARGS...: tstyles ARGS under mpirun with N processes (oversubscribed: CI has 2 cores;
# unbound, so that llvmpipe's threads in one or two processes are not held to one core each).
run_mpi() {
    local processes=$1
    shift
    echo "+ $MPIEXEC -np $processes tstyles $*" >&2
    RC=0
    "$MPIEXEC" -np "$processes" --oversubscribe --bind-to none "$TSTYLES" "$@" >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
}

SCENE="$SOURCE_DIR/data/scenes/figure4-temporal-mip.json"

# expect_same_as_one_process ONE OTHER [MEAN]: the images within the thresholds of
# tests/distributed/distributed_equivalence.cpp, which says why they are not 0 (MEAN: another
# mean difference limit, where the case says why).
expect_same_as_one_process() {
    run_tstyles -- compare "$1" "$2" --max-difference 28 --pixel-threshold 3 --max-failing-share 0.02 \
        --max-mean "${3:-0.03}" --min-ssim 0.999
    expect_exit 0
}

case_four_processes_match_one() {
    run_tstyles -- render "$SCENE" -o "$SCRATCH/one.png" --width 192 --height 192
    expect_exit 0
    run_mpi 4 render "$SCENE" -o "$SCRATCH/four.png" --width 192 --height 192 --distributed
    expect_exit 0
    expect_stdout_contains "4 processes: render"
    expect_stdout_contains "each process read only its block"
    expect_image "$SCRATCH/four.png" 192 192
    expect_same_as_one_process "$SCRATCH/one.png" "$SCRATCH/four.png"
}

# Framing the visible data needs the values: each process reads only its block, the visible bounds
# are taken over the blocks, and the image is the one process's; with `--frame K` of an orbit too,
# whose distance follows the framed bounds.
case_blocks_where_the_scene_needs_values() {
    sed 's#"fov_deg": 30}#"fov_deg": 30, "frame": "visible"}#; s#"\.\./superellipsoid/#"'"$SOURCE_DIR"'/data/superellipsoid/#' \
        "$SCENE" >"$SCRATCH/visible.json"
    grep -q '"frame": "visible"' "$SCRATCH/visible.json" || fail "the scene was not rewritten"
    run_tstyles -- render "$SCRATCH/visible.json" -o "$SCRATCH/one.png" --width 128 --height 128
    expect_exit 0
    run_mpi 2 render "$SCRATCH/visible.json" -o "$SCRATCH/two.png" --width 128 --height 128 --distributed
    expect_exit 0
    expect_stdout_contains "each process read only its block"
    expect_same_as_one_process "$SCRATCH/one.png" "$SCRATCH/two.png"
    run_tstyles -- render "$SCRATCH/visible.json" -o "$SCRATCH/one-frame.png" --width 96 --height 96 \
        --orbit 90 --frames 4 --frame 1
    expect_exit 0
    run_mpi 2 render "$SCRATCH/visible.json" -o "$SCRATCH/two-frame.png" --width 96 --height 96 --distributed \
        --orbit 90 --frames 4 --frame 1
    expect_exit 0
    expect_stdout_contains "each process read only its block"
    expect_same_as_one_process "$SCRATCH/one-frame.png" "$SCRATCH/two-frame.png"
}

# A manifest given alone takes the automatic scene, whose opacity comes from the histogram, its
# gradient range from the changes over time and its camera from the visible bounds: all taken over
# the blocks, so the processes read only their blocks and the picture is the one process's; and
# `animate` plans its frames (an orbit's distance) from the scene so fitted.
case_automatic_scene_in_blocks() {
    local hurricane="$SOURCE_DIR/data/hurricane/series.json"
    run_tstyles -- render "$hurricane" -o "$SCRATCH/one.png" --width 128 --height 128 --tc temporal-max-change
    expect_exit 0
    run_mpi 2 render "$hurricane" -o "$SCRATCH/two.png" --width 128 --height 128 --tc temporal-max-change --distributed
    expect_exit 0
    expect_stdout_contains "each process read only its block"
    expect_same_as_one_process "$SCRATCH/one.png" "$SCRATCH/two.png"
    run_tstyles -- animate "$hurricane" --orbit 90 --frames 3 --width 64 --height 64 -o "$SCRATCH/one/"
    expect_exit 0
    run_mpi 2 animate "$hurricane" --orbit 90 --frames 3 --width 64 --height 64 -o "$SCRATCH/two/" --distributed
    expect_exit 0
    expect_stdout_contains "each process read only its block"
    # The automatic camera sees the hurricane, a slab, from above (docs/automatic-scene.md): more
    # rays reach the termination opacity in the upper block, whose last 1 % the lower one then
    # adds, so the mean difference is larger than the paper scenes' (measured 0.0314/255 at 64x64,
    # 0.0287 and 0.0289 at 128x128, max 2/255); 0.04 is 1.3 times the largest.
    for frame in 0000 0002; do
        expect_same_as_one_process "$SCRATCH/one/frame-$frame.png" "$SCRATCH/two/frame-$frame.png" 0.04
    done
}

# A map's automatic scene draws the largest change along each column, which one process reduces
# on its own: under --distributed the automatic rays composite instead (the over operator merges
# the processes' frames), and the picture is one process's composited one (without the coast,
# which the drawing process cannot take from values it does not hold: docs/annotations.md).
case_automatic_map_composites() {
    "$WRITE_REALISTIC_DATASETS" "$SCRATCH/data" >/dev/null || fail "write_realistic_datasets failed"
    local ocean="$SCRATCH/data/ocean-anomalies.nc"
    run_tstyles -- scene "$ocean" -o "$SCRATCH/composite.json" --ray composite
    expect_exit 0
    sed -i 's/"coast": true/"coast": false/' "$SCRATCH/composite.json"
    grep -q '"coast": false' "$SCRATCH/composite.json" || fail "the scene has no coast to turn off"
    run_tstyles -- render "$SCRATCH/composite.json" -o "$SCRATCH/one.png" --width 96 --height 96
    expect_exit 0
    run_mpi 2 render "$ocean" -o "$SCRATCH/two.png" --width 96 --height 96 --distributed
    expect_exit 0
    expect_same_as_one_process "$SCRATCH/one.png" "$SCRATCH/two.png"
}

# The hurricane takes 23.4 MB under the memory check (4 bytes a voxel in memory, 2 on the GPU), so
# --max-memory 16M refuses it whole; four processes each hold a block (about 7.9 MB with the
# largest time-step while it is read) and render it.
case_blocks_fit_where_the_whole_series_does_not() {
    local hurricane="$SOURCE_DIR/data/scenes/figure5-focus-step5.json"
    run_tstyles -- render "$hurricane" -o "$SCRATCH/one.png" --width 64 --height 64 --max-memory 16M
    expect_exit 2
    expect_stderr_contains "--max-memory"
    expect_no_output "$SCRATCH/one.png"
    run_mpi 4 render "$hurricane" -o "$SCRATCH/four.png" --width 64 --height 64 --max-memory 16M --distributed
    expect_exit 0
    expect_stdout_contains "each process read only its block"
    expect_image "$SCRATCH/four.png" 64 64
    run_tstyles -- render "$hurricane" -o "$SCRATCH/unlimited.png" --width 64 --height 64
    expect_exit 0
    expect_same_as_one_process "$SCRATCH/unlimited.png" "$SCRATCH/four.png"
}

case_without_mpirun_is_one_process() {
    run_tstyles -- render "$SCENE" -o "$SCRATCH/alone.png" --width 96 --height 96 --distributed
    expect_exit 0
    expect_stdout_contains "1 processes: render"
    expect_image "$SCRATCH/alone.png" 96 96
}

# The sonar's pings are cut to the beams and range bins each block needs: the largest of two
# processes' blocks holds fewer than the survey's 6.6 M voxels (5.1 M measured: its ten fans overlap
# across the cut), and the picture is the one process's.
case_sonar_beam_grids_cut() {
    local sonar="$SOURCE_DIR/data/scenes/figure6-centre-index-tstf.json"
    run_tstyles -- render "$sonar" -o "$SCRATCH/one.png" --width 96 --height 96
    expect_exit 0
    run_mpi 2 render "$sonar" -o "$SCRATCH/two.png" --width 96 --height 96 --distributed
    expect_exit 0
    expect_stdout_contains "2 processes: render"
    expect_stdout_contains "each process read only its block"
    local largest
    largest=$(grep -o 'largest block [0-9.e+]* voxels' "$OUT_FILE" | awk '{print $3}')
    awk -v largest="$largest" 'BEGIN { exit !(largest > 0 && largest < 0.85 * 6595000) }' ||
        fail "the largest block holds $largest voxels, not fewer than the survey's 6.6 M"
    expect_same_as_one_process "$SCRATCH/one.png" "$SCRATCH/two.png"
}

case_failure_on_one_process_ends_all() {
    # Only process 0 writes, so only it checks the output folder; the others must not wait for it.
    run_mpi 3 render "$SCENE" -o "$SCRATCH/missing/out.png" --distributed --width 64 --height 64
    expect_exit 2
    expect_stderr_contains "tstyles: process 0 of 3: "
    expect_stderr_contains "missing"
    [ "$(grep -c "process [12] of 3" "$ERR_FILE")" -eq 0 ] || fail "processes 1 and 2 did not fail, yet are reported"
}

# With "value_range" in the manifest each process reads only its block's rows, so a bad value is
# found by the process whose block holds it: an Inf in the last value of a converted CF NetCDF ends
# both processes with that one process's message, exit 2, and no image.
case_bad_value_in_one_block_ends_all() {
    "$(dirname "$TSTYLES")/tests/write_realistic_datasets" "$SCRATCH/real" >/dev/null || fail "write_realistic_datasets failed"
    run_tstyles -- convert "$SCRATCH/real/ocean-eddy.nc" -o "$SCRATCH/eddy"
    expect_exit 0
    grep -q '"value_range"' "$SCRATCH/eddy/series.json" || fail "convert wrote no value_range"
    local bytes
    bytes=$(stat -c %s "$SCRATCH/eddy/t00.raw")
    printf '\x00\x00\x80\x7f' | dd of="$SCRATCH/eddy/t00.raw" bs=1 seek=$((bytes - 4)) conv=notrunc status=none
    run_mpi 2 render "$SCRATCH/eddy" -o "$SCRATCH/bad.png" --width 64 --height 64 --distributed
    expect_exit 2
    expect_stderr_contains "holds a non-finite value (Inf) at voxel (x, y, z) = (79, 59, 19)"
    [ "$(grep -c "tstyles: process [01] of 2: " "$ERR_FILE")" -eq 1 ] || fail "not exactly one process reported the value"
    expect_no_output "$SCRATCH/bad.png"
}

case_animate_frames_match_one() {
    # The growing multiple exposure, 80 frames at 64x64; the first, a middle and the last compared.
    run_tstyles -- animate "$SCENE" --exposure grow --width 64 --height 64 -o "$SCRATCH/one/"
    expect_exit 0
    run_mpi 2 animate "$SCENE" --exposure grow --width 64 --height 64 -o "$SCRATCH/two/" --distributed
    expect_exit 0
    expect_stdout_contains "80 frames as PNG"
    expect_stdout_contains "2 processes, sort-last"
    for frame in 0000 0040 0079; do
        expect_same_as_one_process "$SCRATCH/one/frame-$frame.png" "$SCRATCH/two/frame-$frame.png"
    done
}

# --- check --distributed ------------------------------------------------------------------------
SCENES="$SOURCE_DIR/data/scenes"

# Five 64x64 cases, so that 3 processes take two rounds and process 0 gets cases 1 and 4.
# `focus6` is held to the golden of `focus3` (another picture): it fails once that golden exists.
write_check_suite() {
    mkdir -p "$SCRATCH/golden"
    cat >"$SCRATCH/suite.json" <<JSON
{
  "thresholds": {"max_difference": 2},
  "cases": [
    {"name": "focus3", "scene": "$SCENES/figure1-focus-step3.json", "golden": "golden/focus3.png", "width": 64, "height": 64},
    {"name": "focus6", "scene": "$SCENES/figure1-focus-step6.json", "golden": "golden/focus3.png", "width": 64, "height": 64},
    {"name": "mip", "scene": "$SCENES/figure4-temporal-mip.json", "golden": "golden/mip.png", "width": 64, "height": 64},
    {"name": "average", "scene": "$SCENES/figure4-temporal-average.json", "golden": "golden/average.png", "width": 64, "height": 64},
    {"name": "styled", "scene": "$SCENES/figure1-styled-focus-step3.json", "golden": "golden/styled.png", "width": 64, "height": 64}
  ]
}
JSON
}

# Passing, failing and missing-golden cases: 3 processes print the table of one process, write the
# same report (images compared as files: they travelled as floats) and exit 1 as it does.
case_check_matches_one_process() {
    write_check_suite
    run_tstyles -- check "$SCRATCH/suite.json" --update focus3,mip,styled --report "$SCRATCH/report"
    expect_exit 1  # `average` has no golden
    run_tstyles -- check "$SCRATCH/suite.json" --report "$SCRATCH/report-one"
    expect_exit 1
    cp "$OUT_FILE" "$SCRATCH/stdout-one.txt"
    run_mpi 3 check "$SCRATCH/suite.json" --report "$SCRATCH/report-three" --distributed
    expect_exit 1
    cp "$OUT_FILE" "$SCRATCH/stdout-three.txt"
    head -n 1 "$OUT_FILE" | grep -qx "5 cases over 3 MPI processes, one at a time each (--distributed: case k on process (k-1) mod 3)" ||
        fail "the first line does not say how the cases are spread"
    [ "$(grep -c '^\[[1-5]/5\] [a-z0-9]*: ' "$OUT_FILE")" = 5 ] || fail "not one progress line per case"
    expect_stdout_contains "2 of 5 cases fail"
    diff <(table_of "$SCRATCH/stdout-one.txt") <(table_of "$SCRATCH/stdout-three.txt") >&2 ||
        fail "the tables of one process and of three differ"
    grep -q "^\[2/5\] focus6  *FAIL" <(table_of "$SCRATCH/stdout-three.txt") || fail "focus6 did not fail"
    grep -q "^\[4/5\] average  *NO GOLDEN" <(table_of "$SCRATCH/stdout-three.txt") || fail "average has a golden"
    diff <(junit_without_times "$SCRATCH/report-one/junit.xml") <(junit_without_times "$SCRATCH/report-three/junit.xml") >&2 ||
        fail "junit.xml of one process and of three differ"
    diff -r "$SCRATCH/report-one" "$SCRATCH/report-three" -x junit.xml >&2 ||
        fail "the reports (index.html, images) of one process and of three differ"
    expect_image "$SCRATCH/report-three/focus6.actual.png" 64 64
}

# --update of one case (the third, rendered by process 2) writes the golden one process writes,
# and no other.
case_check_update_distributed() {
    write_check_suite
    run_tstyles -- check "$SCRATCH/suite.json" --update mip --report "$SCRATCH/report"
    expect_exit 1  # the other cases have no goldens
    mv "$SCRATCH/golden/mip.png" "$SCRATCH/mip-one.png"
    run_mpi 3 check "$SCRATCH/suite.json" --update mip --report "$SCRATCH/report" --distributed
    expect_exit 1
    expect_stdout_contains "new golden $SCRATCH/golden/mip.png"
    expect_image "$SCRATCH/golden/mip.png" 64 64
    [ "$(find "$SCRATCH/golden" -type f | wc -l)" -eq 1 ] || fail "goldens other than mip.png were written"
    run_tstyles -- compare "$SCRATCH/mip-one.png" "$SCRATCH/golden/mip.png" --max-difference 0
    expect_exit 0
}

# A bad suite fails on process 0 before anything renders: exit 2, one message, no report.
case_check_bad_suite_distributed() {
    printf '{"cases": [{"scene": "%s", "tolerance": 3}]}\n' "$SCENES/figure1-focus-step3.json" >"$SCRATCH/suite.json"
    run_mpi 3 check "$SCRATCH/suite.json" --report "$SCRATCH/report" --distributed
    expect_exit 2
    expect_stderr_contains "tstyles: process 0 of 3: $SCRATCH/suite.json: cases[0].tolerance: unknown key"
    [ "$(grep -c '^tstyles: ' "$ERR_FILE")" -eq 1 ] || fail "not one message"
    [ "$(grep -c 'process [12] of 3' "$ERR_FILE")" -eq 0 ] || fail "processes 1 and 2 are reported"
    [ ! -e "$SCRATCH/report" ] || fail "a report was written for a bad suite"
}

# A case that cannot be rendered (its dataset does not exist) on process 1 ends every process:
# exit 2, the case named, no report and no golden.
case_check_bad_case_distributed() {
    write_check_suite
    sed 's|"dataset": "[^"]*"|"dataset": "nowhere/series.json"|' "$SCENES/figure1-focus-step6.json" >"$SCRATCH/bad.json"
    sed -i "s|\"scene\": \"$SCENES/figure1-focus-step6.json\"|\"scene\": \"$SCRATCH/bad.json\"|" "$SCRATCH/suite.json"
    grep -q bad.json "$SCRATCH/suite.json" || fail "the test did not write its bad suite"
    run_mpi 3 check "$SCRATCH/suite.json" --update --all --report "$SCRATCH/report" --distributed
    expect_exit 2
    expect_stderr_contains "tstyles: process 1 of 3: case \"focus6\" ($SCRATCH/bad.json): "
    expect_stderr_contains "nowhere/series.json"
    [ "$(grep -c '^tstyles: ' "$ERR_FILE")" -eq 1 ] || fail "not one message"
    [ ! -e "$SCRATCH/report" ] || fail "a report was written after a bad case"
    [ -z "$(find "$SCRATCH/golden" -type f)" ] || fail "goldens were written after a bad case"
}

# --jobs is refused with --distributed (each process renders one case at a time), once.
case_check_jobs_refused_distributed() {
    write_check_suite
    run_mpi 2 check "$SCRATCH/suite.json" --jobs 2 --report "$SCRATCH/report" --distributed
    expect_exit 2
    expect_stderr_contains "tstyles: process 0 of 2: --jobs: goes without --distributed"
    [ "$(grep -c '^tstyles: ' "$ERR_FILE")" -eq 1 ] || fail "not one message"
    [ ! -e "$SCRATCH/report" ] || fail "a report was written"
}

# A dataset that is not read in blocks is read whole by every process, each in a reader process of
# its own (docs/readers.md, "How reading is isolated"): a NetCDF file reads and renders as with one
# process, and libhdf5's crash on a damaged one ends all processes with the message, exit 2.
case_reader_processes_under_mpi() {
    "$(dirname "$TSTYLES")/tests/write_reader_samples" "$SCRATCH/samples" || fail "write_reader_samples failed"
    run_tstyles -- render "$SCRATCH/samples/ocean.nc" --var temp -o "$SCRATCH/one.png" --width 64 --height 64
    expect_exit 0
    run_mpi 2 render "$SCRATCH/samples/ocean.nc" --var temp -o "$SCRATCH/two.png" --width 64 --height 64 --distributed
    expect_exit 0
    expect_same_as_one_process "$SCRATCH/one.png" "$SCRATCH/two.png"
    cp "$SOURCE_DIR/tests/data/damaged/netcdf4_hdf5_segv.nc" "$SCRATCH/segv.nc"
    run_mpi 2 render "$SCRATCH/segv.nc" --var temp -o "$SCRATCH/bad.png" --width 64 --height 64 --distributed
    expect_exit 2
    expect_stderr_contains "$SCRATCH/segv.nc: the NetCDF/HDF5 library crashed while reading the variable list: the file is damaged"
    [ ! -e "$SCRATCH/bad.png" ] || fail "an image was written"
}

run_case
