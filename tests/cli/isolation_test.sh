#!/usr/bin/env bash
# A damaged file never takes the program down (issue 38): files on which libhdf5 crashes or never
# returns are read in a reader process; `info`, `render`, `convert` and the window end them with
# one line naming the library and the stage, exit 2 (the window: an error dialog, the scene kept),
# within 40 s (a silent reader is ended after 30 s), leaving no process and no temporary file
# behind. TSTYLES_READ_IN_PROCESS=1 reads in the program's own process again (docs/readers.md,
# "How reading is isolated").
# Usage: isolation_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

SAMPLES_WRITER="$(dirname "$TSTYLES")/tests/write_reader_samples"
# Found by mutating a small NetCDF-4 file: a segmentation fault and an endless loop inside libhdf5
# (H5DSget_num_scales -> H5Aread -> H5HG_read) while the variables are listed.
# Each case reads its own copy, so a process left behind is told apart from the parallel cases' ones.
SEGV="$SCRATCH/netcdf4_hdf5_segv.nc"
HANG="$SCRATCH/netcdf4_hdf5_dimscale_hang.nc"
cp "$SOURCE_DIR/tests/data/damaged/netcdf4_hdf5_segv.nc" "$SOURCE_DIR/tests/data/damaged/netcdf4_hdf5_dimscale_hang.nc" \
    "$SCRATCH/"
CRASHED="the NetCDF/HDF5 library crashed while reading the variable list: the file is damaged"
STOPPED="the NetCDF/HDF5 library stopped responding while reading the variable list"

# Runs tstyles in a temporary folder of its own, within 40 s (the 30 s of silence a reader is
# allowed, and the time to end it and report); afterwards nothing may be left: no file in that
# folder, no process reading the file (a reader is a fork: it has tstyles' command line).
run_isolated() {
    local start=$SECONDS file=$1
    shift
    mkdir -p "$SCRATCH/tmp"
    RC=0
    echo "+ timeout 60 tstyles $*" >&2
    TMPDIR="$SCRATCH/tmp" timeout 60 "$TSTYLES" "$@" >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
    [ "$RC" != 124 ] || fail "tstyles $* did not finish within 60 s"
    [ $((SECONDS - start)) -le 40 ] || fail "tstyles $* took $((SECONDS - start)) s"
    [ -z "$(ls -A "$SCRATCH/tmp")" ] || fail "temporary files left behind: $(ls -A "$SCRATCH/tmp")"
    ! pgrep -f -- "$file" >/dev/null || fail "a process reading $file is still running: $(pgrep -af -- "$file")"
}

case_segv_info() {
    run_isolated "$SEGV" info "$SEGV" --var temp
    expect_exit 2
    expect_error_line "$SEGV" "" "$CRASHED"
}

case_segv_render() {
    run_isolated "$SEGV" render "$SEGV" --var temp -o "$SCRATCH/out.png" --backend osmesa --width 64 --height 64
    expect_exit 2
    expect_error_line "$SEGV" "" "$CRASHED"
    expect_no_output "$SCRATCH/out.png"
}

case_segv_convert() {
    run_isolated "$SEGV" convert "$SEGV" --var temp -o "$SCRATCH/converted"
    expect_exit 2
    expect_error_line "$SEGV" "" "$CRASHED"
    [ ! -e "$SCRATCH/converted" ] || fail "convert wrote a folder for a file it could not read"
}

# The silence allowed is 30 s plus 1 s per 50 MiB of input: this 9 KiB file is ended after 30 s.
case_hang_info() {
    run_isolated "$HANG" info "$HANG" --var temp
    expect_exit 2
    expect_error_line "$HANG" "" "$STOPPED (no progress in 30 s; the reader was ended): the file is damaged, or reading it is slower than the deadline allows"
}

case_hang_render() {
    run_isolated "$HANG" render "$HANG" --var temp -o "$SCRATCH/out.png" --backend osmesa --width 64 --height 64
    expect_exit 2
    expect_error_line "$HANG" "" "$STOPPED"
    expect_no_output "$SCRATCH/out.png"
}

# Errors the readers throw come back word for word, and good files read as before.
case_errors_and_series_unchanged() {
    "$SAMPLES_WRITER" "$SCRATCH/samples" || fail "write_reader_samples failed"
    for file in ocean.nc classic.nc volume.nrrd bold.nii.gz nan.nc inf.nc int64.nc; do
        run_tstyles TSTYLES_READ_IN_PROCESS=1 -- info "$SCRATCH/samples/$file" --var temp
        cp "$OUT_FILE" "$SCRATCH/in_process.out"
        cp "$ERR_FILE" "$SCRATCH/in_process.err"
        local in_process_rc=$RC
        run_tstyles -- info "$SCRATCH/samples/$file" --var temp
        [ "$RC" = "$in_process_rc" ] || fail "$file: exit $RC isolated, $in_process_rc in-process"
        cmp -s "$OUT_FILE" "$SCRATCH/in_process.out" || fail "$file: info differs from in-process reading"
        cmp -s "$ERR_FILE" "$SCRATCH/in_process.err" || fail "$file: the error differs from in-process reading"
    done
}

# TSTYLES_READ_IN_PROCESS=1 does read in the program's process: there the library's crash takes
# tstyles down (a signal, or the sanitizer's report), not exit 2.
case_in_process_reading() {
    run_tstyles TSTYLES_READ_IN_PROCESS=1 -- info "$SEGV" --var temp
    [ "$RC" != 0 ] && [ "$RC" != 2 ] || fail "reading in-process survived libhdf5's crash (exit $RC)"
    run_tstyles TSTYLES_READ_IN_PROCESS=0 -- info "$SEGV" --var temp
    expect_exit 2
}

# The window: File > Open of the damaged file shows the error and keeps the scene that was open;
# stdout and stderr hold only the window's own lines, and the script ends it with exit 0.
case_view_keeps_the_scene() {
    if ! command -v xvfb-run >/dev/null; then
        echo "SKIP [$CASE]: xvfb-run not found (package xvfb)"
        return
    fi
    printf 'wait-refined\nsave-scene ${OUT}/before.json\nopen %s\nwait 5\nscreenshot-window ${OUT}/error-dialog.png\nkey enter\nwait 3\nsave-scene ${OUT}/after.json\nquit\n' \
        "$SEGV" >"$SCRATCH/script.txt"
    RC=0
    OUT="$SCRATCH" timeout 90 xvfb-run -a -s "-screen 0 1024x768x24" "$TSTYLES" view "$DATASET" --size 800x600 \
        --no-vsync --script "$SCRATCH/script.txt" >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
    expect_exit 0
    [ -f "$SCRATCH/error-dialog.png" ] || fail "no screenshot of the error dialog"
    cmp -s "$SCRATCH/before.json" "$SCRATCH/after.json" || fail "the scene changed after the failed open"
    # The error dialog echoes its message on stderr (viewer_dialogs.cpp); nothing else may be there.
    [ "$(cat "$ERR_FILE")" = "tstyles view: $SEGV: $CRASHED" ] || fail "stderr is not the dialog's one line"
    ! pgrep -f -- "$SEGV" >/dev/null || fail "a reader process of $SEGV is still running"
}

run_case
