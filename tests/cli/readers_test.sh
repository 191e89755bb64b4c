#!/usr/bin/env bash
# End-to-end: scientists' files (NetCDF, NIfTI, NRRD, Plot3D, Hurricane Isabel raw) through
# `tstyles info`, `convert` and `render`, with the reading options; bad files and bad options end in
# exit code 2, one line naming the file and the problem, and nothing written.
# Usage: readers_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

# Both helpers are built beside tstyles: the sample writer under tests/, the warped box under tools/.
SAMPLES_WRITER="$(dirname "$TSTYLES")/tests/write_reader_samples"
GENERATOR="$(dirname "$TSTYLES")/tools/generate_warped_box"

# The files write_reader_samples.cpp describes: ocean.nc, notime.nc, nan.nc, inf.nc, int64.nc, volume.nrrd,
# bold.nii.gz, QCLOUDf01.bin .. QCLOUDf03.bin.
samples() {
    S="$SCRATCH/samples"
    "$SAMPLES_WRITER" "$S" || fail "write_reader_samples failed"
}

# The first float32 (little-endian, as the manifest's raw files are) at value index $2 of file $1.
float_at() {
    od -A n -t f4 -j $(($2 * 4)) -N 4 "$1" | tr -d ' '
}

# A bad option, not a bad file: one line "tstyles: OPTION: PROBLEM".
expect_option_error() {
    [ "$(wc -l <"$ERR_FILE")" -eq 1 ] || fail "expected exactly one line on stderr"
    case "$(cat "$ERR_FILE")" in
        "tstyles: $1: "*) ;;
        *) fail "stderr does not start with 'tstyles: $1: '" ;;
    esac
    expect_stderr_contains "$2"
}

STF='"stf": {"opacity": [{"at": 0.0, "opacity": 0.1}, {"at": 1.0, "opacity": 0.9}], "color": [{"at": 0, "color": [0, 0.4, 1]}, {"at": 1, "color": [1, 0.6, 0]}]}'

case_info_netcdf() {
    samples
    run_tstyles -- info "$S/ocean.nc" --var temp
    expect_exit 0
    expect_stdout_contains "Format: NetCDF-4"
    expect_stdout_contains "Time-steps: 3"
    # Values 1..59, 101..159, 201..259; the fill value at one voxel per step is missing.
    expect_stdout_contains "Value range: [1, 259]"
    expect_stdout_contains "Missing values: 3 voxels without data"
    expect_stdout_contains "rectilinear 5x4x3"
    expect_stdout_contains "(1, 1, uneven)"
    # Without --var the two 4D variables are a choice the user must make.
    run_tstyles -- info "$S/ocean.nc"
    expect_exit 2
    expect_error_line "$S/ocean.nc" "" "salt"
}

case_info_netcdf_steps_range() {
    samples
    run_tstyles -- info "$S/ocean.nc" --var temp --steps 1:3 --range 0:300
    expect_exit 0
    expect_stdout_contains "Time-steps: 2"
    expect_stdout_contains "Value range: [0, 300]"
    run_tstyles -- info "$S/ocean.nc" --var temp --steps 5:
    expect_exit 2
    expect_error_line "$S/ocean.nc" "--steps" "selects no time-step"
    run_tstyles -- info "$S/ocean.nc" --var temp --range 3:1
    expect_exit 2
    expect_option_error "--range" "LOW must be less than HIGH"
}

case_info_nrrd() {
    samples
    run_tstyles -- info "$S/volume.nrrd"
    expect_exit 0
    expect_stdout_contains "Format: NRRD"
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "Value range: [0, 48]"
    expect_stdout_contains "(0.5, 1, 2)"
    expect_stdout_contains "(1, 2, 3)"
}

case_info_nifti() {
    samples
    run_tstyles -- info "$S/bold.nii.gz"
    expect_exit 0
    expect_stdout_contains "Format: NIfTI-1"
    expect_stdout_contains "Time-steps: 2"
    expect_stdout_contains "Value range: [0, 23]"
    expect_stdout_contains "(2, 3, 4)"
}

case_info_isabel() {
    samples
    run_tstyles -- info "$S/QCLOUDf01.bin" "$S/QCLOUDf02.bin" "$S/QCLOUDf03.bin" --dims 6x5x4
    expect_exit 0
    expect_stdout_contains "Format: Hurricane Isabel raw"
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "Value range: [1.006, 3.119]"
    expect_stdout_contains "Missing values: 18 voxels without data"
    # Without --dims the files are too small for 500 x 500 x 100.
    run_tstyles -- info "$S/QCLOUDf01.bin"
    expect_exit 2
    expect_error_line "$S/QCLOUDf01.bin"
}

case_info_plot3d() {
    "$GENERATOR" --plot3d --output "$SCRATCH/plot3d" --steps 2 >/dev/null || fail "generate_warped_box failed"
    run_tstyles -- info "$SCRATCH/plot3d/grid.xyz" --solution "$SCRATCH/plot3d/flow00.q,$SCRATCH/plot3d/flow01.q" \
        --var pressure --steps 1:
    expect_exit 0
    expect_stdout_contains "Format: Plot3D"
    expect_stdout_contains "Time-steps: 1"
    expect_stdout_contains "structured 33x33x17"
    run_tstyles -- info "$SCRATCH/plot3d/grid.xyz" --solution "$SCRATCH/plot3d/flow00.q" --resample 8x8x8
    expect_exit 2
    expect_error_line "$SCRATCH/plot3d/grid.xyz" "--resample" "structured"
    run_tstyles -- info "$SCRATCH/plot3d/grid.xyz" --solution "$SCRATCH/plot3d/flow00.q" --block 1
    expect_exit 2
    expect_error_line "$SCRATCH/plot3d/grid.xyz" "" "block 1 was asked for"
    # gamma scales pressure, (gamma - 1) (E - |m|^2 / 2 rho): 2.2 gives 3 times the range of 1.4.
    local low high
    run_tstyles -- info "$SCRATCH/plot3d/grid.xyz" --solution "$SCRATCH/plot3d/flow00.q" --var pressure
    expect_exit 0
    low=$(sed -n 's/^Value range: \[\(.*\), \(.*\)\] .*/\1 \2/p' "$OUT_FILE")
    run_tstyles -- info "$SCRATCH/plot3d/grid.xyz" --solution "$SCRATCH/plot3d/flow00.q" --var pressure --gamma 2.2
    expect_exit 0
    high=$(sed -n 's/^Value range: \[\(.*\), \(.*\)\] .*/\1 \2/p' "$OUT_FILE")
    awk -v a="$low" -v b="$high" 'BEGIN { split(a, x, " "); split(b, y, " ");
        exit !(x[2] != 0 && (y[2] / x[2] - 3) ^ 2 < 1e-8 && (y[1] - 3 * x[1]) ^ 2 < 1e-8 * (1 + x[1] ^ 2)) }' ||
        fail "pressure ranges with gamma 1.4 [$low] and 2.2 [$high] are not 3 times apart"
}

case_index_axes() {
    samples
    run_tstyles -- info "$S/ocean.nc" --var temp --index-axes
    expect_exit 0
    expect_stdout_contains "(1, 1, 1)"
}

case_precision_in_info() {
    samples
    run_tstyles -- info "$S/volume.nrrd" --precision 8
    expect_exit 0
    expect_stdout_contains "(8-bit density per voxel)"
    run_tstyles -- info "$S/ocean.nc" --var temp --precision 32
    expect_exit 0
    expect_stdout_contains "(32-bit density + validity per voxel)"
    run_tstyles -- info "$S/volume.nrrd" --precision 12
    expect_exit 2
    expect_option_error "--precision" "must be 8, 16 or 32; got \"12\""
}

case_resample() {
    samples
    run_tstyles -- info "$S/volume.nrrd" --resample 7x5x3
    expect_exit 0
    expect_stdout_contains "rectilinear 7x5x3"
    # The same extent: 3 x 0.5 = 1.5 along x over 6 cells.
    expect_stdout_contains "(0.25, 0.5, 1)"
}

# 60 voxels per step at 4 bytes in memory + 2 on the GPU: 360 bytes a step, 1080 for three.
case_fit_steps() {
    samples
    run_tstyles -- info "$S/ocean.nc" --var temp --max-memory 800 --fit steps
    expect_exit 0
    expect_stdout_contains "Time-steps: 2"
}

case_fit_resolution() {
    samples
    run_tstyles -- info "$S/ocean.nc" --var temp --max-memory 800 --fit resolution
    expect_exit 0
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "rectilinear 4x3x2"
}

case_over_max_memory() {
    samples
    run_tstyles -- info "$S/ocean.nc" --var temp --max-memory 800
    expect_exit 2
    expect_error_line "$S/ocean.nc" "--max-memory" "needs 1080 bytes"
    expect_stderr_contains "more than the 800 bytes allowed"
    write_scene "$SCRATCH/scene.json" "$S/ocean.nc" "$STF"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --backend osmesa --var temp --max-memory 800
    expect_exit 2
    expect_error_line "$S/ocean.nc" "--max-memory" "needs"
    expect_no_output "$SCRATCH/out.png"
    run_tstyles -- convert "$S/ocean.nc" -o "$SCRATCH/out" --var temp --max-memory 800
    expect_exit 2
    [ ! -e "$SCRATCH/out" ] || fail "convert failed but created $SCRATCH/out"
}

case_fit_without_max_memory() {
    samples
    run_tstyles -- info "$S/volume.nrrd" --fit steps
    expect_exit 2
    expect_option_error "--fit" "--max-memory"
}

case_convert_netcdf() {
    samples
    run_tstyles -- convert "$S/ocean.nc" --var temp -o "$SCRATCH/out"
    expect_exit 0
    [ -f "$SCRATCH/out/series.json" ] || fail "no series.json"
    [ -z "$(find "$SCRATCH" -maxdepth 1 -name '.*tmp*')" ] || fail "temporary folders left behind"
    # The raw values as read: step 1 holds 100 + index; its first voxel is the fill value (NaN).
    [ "$(float_at "$SCRATCH/out/t01.raw" 5)" = "105" ] || fail "t01.raw[5] is $(float_at "$SCRATCH/out/t01.raw" 5)"
    [ "$(float_at "$SCRATCH/out/t01.raw" 0)" = "nan" ] || fail "t01.raw[0] is $(float_at "$SCRATCH/out/t01.raw" 0)"
    run_tstyles -- info "$SCRATCH/out"
    expect_exit 0
    expect_stdout_contains "Format: tstyles manifest"
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "Value range: [1, 259]"
    expect_stdout_contains "Missing values: 3 voxels without data"
    expect_stdout_contains "(1, 1, uneven)"
}

case_convert_refuses_nonempty() {
    samples
    mkdir -p "$SCRATCH/out"
    echo keep >"$SCRATCH/out/notes.txt"
    run_tstyles -- convert "$S/volume.nrrd" -o "$SCRATCH/out"
    expect_exit 2
    expect_error_line "$SCRATCH/out" "" "not empty"
    [ -f "$SCRATCH/out/notes.txt" ] || fail "the existing folder was touched"
    [ ! -e "$SCRATCH/out/series.json" ] || fail "series.json written into a folder that was not empty"
    [ -z "$(find "$SCRATCH" -maxdepth 1 -name '.*tmp*')" ] || fail "temporary folders left behind"
}

case_convert_force() {
    samples
    mkdir -p "$SCRATCH/out"
    echo old >"$SCRATCH/out/notes.txt"
    run_tstyles -- convert "$S/volume.nrrd" -o "$SCRATCH/out" --force
    expect_exit 0
    [ ! -e "$SCRATCH/out/notes.txt" ] || fail "the old folder's content is still there"
    [ "$(float_at "$SCRATCH/out/t02.raw" 3)" = "8" ] || fail "t02.raw[3] is $(float_at "$SCRATCH/out/t02.raw" 3)"
    [ -z "$(find "$SCRATCH" -maxdepth 1 -name '.*tmp*')" ] || fail "temporary folders left behind"
}

case_convert_isabel() {
    samples
    run_tstyles -- convert "$S"/QCLOUDf0?.bin --dims 6x5x4 --steps 0:3:2 -o "$SCRATCH/out"
    expect_exit 0
    run_tstyles -- info "$SCRATCH/out"
    expect_exit 0
    expect_stdout_contains "Time-steps: 2"
    expect_stdout_contains "Missing values: 12 voxels without data"
    [ "$(float_at "$SCRATCH/out/t01.raw" 0)" = "nan" ] || fail "the land marker did not become NaN"
}

case_render_netcdf() {
    samples
    write_scene "$SCRATCH/scene.json" "$S/ocean.nc" "$STF"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --backend osmesa --var temp
    expect_exit 0
    expect_stdout_contains "3 time-steps"
    expect_image "$SCRATCH/out.png" 64 64
}

case_render_dataset_option() {
    samples
    write_scene "$SCRATCH/scene.json" "$DATASET" "$STF"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --backend osmesa --dataset "$S/volume.nrrd" \
        --steps 0:2
    expect_exit 0
    expect_stdout_contains "2 time-steps"
    expect_image "$SCRATCH/out.png" 64 64
}

# The densities of this uint8 volume (0 .. 48 over [0, 1]) are not multiples of 1/255 or 1/65535:
# stored in 8 or 16 bits they round, so each precision gives its own bytes, and the same picture.
# Measured: 8 against 32 bits at most 2/255, mean 0.072/255; 16 against 32 at most 1/255.
case_render_precision() {
    samples
    write_scene "$SCRATCH/scene.json" "$S/volume.nrrd" "$STF"
    for bits in 8 16 32; do
        run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out$bits.png" --backend osmesa --precision $bits
        expect_exit 0
        expect_image "$SCRATCH/out$bits.png" 64 64
    done
    for bits in 8 16; do
        ! cmp -s "$SCRATCH/out$bits.png" "$SCRATCH/out32.png" || fail "--precision $bits rendered the 32-bit image"
        run_tstyles -- compare "$SCRATCH/out32.png" "$SCRATCH/out$bits.png" --max-difference 4 --max-mean 0.15 \
            --max-failing-share 0.5
        expect_exit 0
    done
}

case_truncated_netcdf() {
    samples
    truncate -s 600 "$S/ocean.nc"
    run_tstyles -- info "$S/ocean.nc" --var temp
    expect_exit 2
    expect_error_line "$S/ocean.nc" "" "truncated or damaged? 600 bytes"
}

case_truncated_nrrd() {
    samples
    truncate -s 250 "$S/volume.nrrd"
    run_tstyles -- convert "$S/volume.nrrd" -o "$SCRATCH/out"
    expect_exit 2
    expect_error_line "$S/volume.nrrd" "" "truncated"
    [ ! -e "$SCRATCH/out" ] || fail "convert failed but created $SCRATCH/out"
}

case_unknown_variable() {
    samples
    run_tstyles -- info "$S/ocean.nc" --var pressure
    expect_exit 2
    expect_error_line "$S/ocean.nc" "--var" "pressure"
}

case_no_time_dimension() {
    samples
    run_tstyles -- info "$S/notime.nc"
    expect_exit 2
    expect_error_line "$S/notime.nc" "" "time"
}

case_time_dim_option() {
    samples
    run_tstyles -- info "$S/notime.nc" --time-dim a
    expect_exit 0
    expect_stdout_contains "Time-steps: 2"
    expect_stdout_contains "rectilinear 4x3x2"
}

# NaN that no attribute declares is missing data (as napari, Fiji and ParaView read it): counted by
# `info`, out of the range, transparent in the picture. Inf is never a value.
case_nan_is_missing() {
    samples
    run_tstyles -- info "$S/nan.nc"
    expect_exit 0
    expect_stdout_contains "Missing values: 1 voxels without data (4.2 %)"
    expect_stdout_contains "Value range: [0, 23]"
    write_scene "$SCRATCH/scene.json" "$S/nan.nc" "$STF"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --backend osmesa --width 64 --height 64
    expect_exit 0
    run_tstyles -- info "$S/inf.nc"
    expect_exit 2
    expect_error_line "$S/inf.nc" "" "time-step 0 holds Inf at voxel (x, y, z) = (1, 0, 1): only NaN"
    write_scene "$SCRATCH/scene.json" "$S/inf.nc" "$STF"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/inf.png" --backend osmesa
    expect_exit 2
    expect_error_line "$S/inf.nc" "" "Inf"
    expect_no_output "$SCRATCH/inf.png"
}

case_unsupported_type() {
    samples
    run_tstyles -- info "$S/int64.nc"
    expect_exit 2
    expect_error_line "$S/int64.nc" "" "type"
}

case_manifest_with_reader_option() {
    run_tstyles -- info "$DATASET" --steps 0:2
    expect_exit 2
    expect_error_line "$DATASET" "--steps" "not to a tstyles manifest"
}

# The reader options' table checks each value and names its bounds in words (issue 53: CLI11's own
# message printed 1.8e308 as the upper bound of --level).
case_option_values_outside_their_bounds() {
    run_tstyles -- info "$DATASET" --level -1
    expect_exit 2
    expect_stderr_contains '--level: must be a whole number 0 or more; got "-1"'
    run_tstyles -- info "$DATASET" --precision 12
    expect_exit 2
    expect_stderr_contains '--precision: must be 8, 16 or 32; got "12"'
    run_tstyles -- info "$DATASET" --level 1
    expect_exit 2
    expect_error_line "$DATASET" "--level" "applies to the files a reader reads (OME-Zarr, TIFF), not to a tstyles manifest"
}

case_solution_on_netcdf() {
    samples
    run_tstyles -- info "$S/ocean.nc" --solution "$S/flow.q"
    expect_exit 2
    expect_error_line "$S/ocean.nc" "--solution" "Plot3D"
}

case_option_for_another_format() {
    samples
    run_tstyles -- info "$S/volume.nrrd" --var temp
    expect_exit 2
    expect_error_line "$S/volume.nrrd" "--var" "does not apply to NRRD files (only to NetCDF and VTK and Plot3D)"
    run_tstyles -- info "$S/ocean.nc" --var temp --dims 6x5x4
    expect_exit 2
    expect_error_line "$S/ocean.nc" "--dims" "only to Hurricane Isabel raw"
}

case_unknown_format() {
    mkdir -p "$SCRATCH/files"
    echo "just some text" >"$SCRATCH/files/notes.txt"
    run_tstyles -- info "$SCRATCH/files/notes.txt"
    expect_exit 2
    expect_error_line "$SCRATCH/files/notes.txt" "" "unknown format"
}

# The viewer on a NetCDF file: it opens with the reading options, saves a scene naming the file,
# and that scene renders headless. Skipped (and said so) where xvfb-run is missing.
case_view_netcdf() {
    have_xvfb || return 0
    samples
    view_and_screenshot "$S/ocean.nc" --var temp --steps 0:2 --size 800x600
    grep -q "ocean.nc" "$SCRATCH/saved.json" || fail "the saved scene does not name ocean.nc"
    run_tstyles -- render "$SCRATCH/saved.json" -o "$SCRATCH/out.png" --backend osmesa --var temp --steps 0:2 \
        --width 64 --height 64
    expect_exit 0
    expect_stdout_contains "2 time-steps"
}

run_case
