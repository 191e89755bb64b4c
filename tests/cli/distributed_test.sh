#!/usr/bin/env bash
# End-to-end: `mpirun -np N tstyles render ... --distributed` (sort-last over MPI processes,
# docs/scaling.md): the image matches one process, and a failure on one process or on all ends
# every process with one message and exit 2 (never a hang: ctest's timeout would show one).
# Usage: distributed_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh); MPIEXEC is
# mpirun, with OMPI_ALLOW_RUN_AS_ROOT set by ctest where the tests run as root.
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"
MPIEXEC=${MPIEXEC:-mpirun}

# run_mpi N ARGS...: tstyles ARGS under mpirun with N processes (oversubscribed: CI has 2 cores).
run_mpi() {
    local processes=$1
    shift
    echo "+ $MPIEXEC -np $processes tstyles $*" >&2
    RC=0
    "$MPIEXEC" -np "$processes" --oversubscribe "$TSTYLES" "$@" >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
}

SCENE="$SOURCE_DIR/data/scenes/figure4-temporal-mip.json"

case_four_processes_match_one() {
    run_tstyles -- render "$SCENE" -o "$SCRATCH/one.png" --width 192 --height 192
    expect_exit 0
    run_mpi 4 render "$SCENE" -o "$SCRATCH/four.png" --width 192 --height 192 --distributed
    expect_exit 0
    expect_stdout_contains "4 processes: render"
    expect_image "$SCRATCH/four.png" 192 192
    # The thresholds of tests/distributed/distributed_equivalence.cpp, which says why they are not 0.
    run_tstyles -- compare "$SCRATCH/one.png" "$SCRATCH/four.png" --max-difference 64 --pixel-threshold 3 \
        --max-failing-share 0.02 --max-mean 0.03 --min-ssim 0.999
    expect_exit 0
}

case_without_mpirun_is_one_process() {
    run_tstyles -- render "$SCENE" -o "$SCRATCH/alone.png" --width 96 --height 96 --distributed
    expect_exit 0
    expect_stdout_contains "1 processes: render"
    expect_image "$SCRATCH/alone.png" 96 96
}

case_beam_grids_refused_on_every_process() {
    run_mpi 2 render "$SOURCE_DIR/data/scenes/figure6-centre-index-tstf.json" -o "$SCRATCH/sonar.png" --distributed \
        --width 64 --height 64
    expect_exit 2
    expect_stderr_contains "tstyles: process 0 of 2: "
    expect_stderr_contains "process 1 of 2: "
    expect_stderr_contains "time-step 0: is a beam grid; distributed rendering splits rectilinear grids only"
    expect_no_output "$SCRATCH/sonar.png"
}

case_failure_on_one_process_ends_all() {
    # Only process 0 writes, so only it checks the output folder; the others must not wait for it.
    run_mpi 3 render "$SCENE" -o "$SCRATCH/missing/out.png" --distributed --width 64 --height 64
    expect_exit 2
    expect_stderr_contains "tstyles: process 0 of 3: "
    expect_stderr_contains "missing"
    [ "$(grep -c "process [12] of 3" "$ERR_FILE")" -eq 0 ] || fail "processes 1 and 2 did not fail, yet are reported"
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
        run_tstyles -- compare "$SCRATCH/one/frame-$frame.png" "$SCRATCH/two/frame-$frame.png" --max-difference 64 \
            --pixel-threshold 3 --max-failing-share 0.02 --max-mean 0.03 --min-ssim 0.999
        expect_exit 0
    done
}

run_case
