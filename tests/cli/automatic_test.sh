#!/usr/bin/env bash
# End-to-end: a dataset with no scene file (docs/automatic-scene.md): `render FILE`, `scene FILE`,
# the overrides, and a written scene refitted to another file. The files come from
# write_realistic_datasets (tests/data/realistic_datasets.h), named by $WRITE_REALISTIC_DATASETS.
# Usage: automatic_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

write_samples() {
    "$WRITE_REALISTIC_DATASETS" "$SCRATCH/data" || fail "write_realistic_datasets failed"
}

# A CF NetCDF renders with no scene: the image is written and is not one colour.
case_render_netcdf() {
    write_samples
    run_tstyles -- render "$SCRATCH/data/ocean-anomalies.nc" -o "$SCRATCH/ocean.png" --width 96 --height 80
    expect_exit 0
    expect_image "$SCRATCH/ocean.png" 96 80
    expect_stdout_contains "(96x80, temporal-mip, largest-change ray, 3 time-steps"
}

# info ends with what the automatic scene chose: a map of degrees with the surface up, seen from
# above as the largest change along each column.
case_info_explains() {
    write_samples
    run_tstyles -- info "$SCRATCH/data/ocean-anomalies.nc"
    expect_exit 0
    expect_stdout_contains "orientation: right = +x (lon, east), up = +z (depth, up), toward the viewer = -y (lat, north)"
    expect_stdout_contains "aspect: map (the axes' units differ: degrees_east, m, degrees_north)"
    expect_stdout_contains "camera: geographic: seen from above, north up, orthographic"
    expect_stdout_contains "ray: largest-change (the sample along each ray whose values change most over time)"
    expect_stdout_contains "unchanged places: no time colour, a faint grey (0.35 of the opacity)"
    run_tstyles -- info "$SCRATCH/data/ct-phantom.nii"
    expect_exit 0
    expect_stdout_contains "transparent"
    expect_stdout_contains "camera: anatomical: seen from the front, head up"
    expect_stdout_contains "unchanged places: no time colour and 0.35 of the opacity on boundaries"
}

# scene writes the automatic parts as "auto", and the scene renders to the same image as the file.
case_scene_round_trip() {
    write_samples
    run_tstyles -- scene "$SCRATCH/data/moving-blob.nii" -o "$SCRATCH/blob.json"
    expect_exit 0
    expect_stdout_contains "wrote $SCRATCH/blob.json, the automatic scene of"
    grep -q '"orientation": "auto"' "$SCRATCH/blob.json" || fail "no automatic orientation in blob.json"
    grep -q '"range": "auto"' "$SCRATCH/blob.json" || fail "no automatic gradient range in blob.json"
    run_tstyles -- render "$SCRATCH/blob.json" -o "$SCRATCH/from-scene.png" --width 64 --height 64
    expect_exit 0
    run_tstyles -- render "$SCRATCH/data/moving-blob.nii" -o "$SCRATCH/from-file.png" --width 64 --height 64
    expect_exit 0
    "$OIIOTOOL" "$SCRATCH/from-scene.png" "$SCRATCH/from-file.png" --diff >/dev/null 2>&1 ||
        fail "the written scene renders differently from the dataset itself"
}

# A compositor for a map's automatic scene: the max density change goes with the largest change
# along each column; the average, which composites the time-steps, turns the rays to composite
# (said in `scene`'s explanation) instead of failing.
case_map_compositors() {
    write_samples
    run_tstyles -- render "$SCRATCH/data/ocean-anomalies.nc" -o "$SCRATCH/change.png" --width 64 --height 64 \
        --tc temporal-max-change
    expect_exit 0
    expect_stdout_contains "temporal-max-change, largest-change ray"
    run_tstyles -- scene "$SCRATCH/data/ocean-anomalies.nc" -o "$SCRATCH/average.json" --tc temporal-average
    expect_exit 0
    expect_stdout_contains "ray composite: temporal-average (--tc) does not go with largest-change"
    run_tstyles -- render "$SCRATCH/average.json" -o "$SCRATCH/average.png" --width 64 --height 64
    expect_exit 0
    expect_image "$SCRATCH/average.png" 64 64
}

# A written scene meets another dataset: its automatic camera and range are fitted to that one.
case_scene_refits_other_dataset() {
    write_samples
    run_tstyles -- scene "$SCRATCH/data/ocean-anomalies.nc" -o "$SCRATCH/ocean.json"
    expect_exit 0
    run_tstyles -- render "$SCRATCH/ocean.json" --dataset "$SCRATCH/data/ocean-eddy.nc" -o "$SCRATCH/eddy.png" \
        --width 64 --height 64
    expect_exit 0
    expect_image "$SCRATCH/eddy.png" 64 64
    expect_stdout_contains "6 time-steps"
}

# Unchanged places from the command line: off, a number with an opacity share, and each refusal
# naming its option, with nothing written.
case_unchanged_options() {
    write_samples
    run_tstyles -- scene "$SCRATCH/data/ct-phantom.nii" -o "$SCRATCH/auto.json"
    expect_exit 0
    grep -q '"below": "auto"' "$SCRATCH/auto.json" || fail "the automatic scene has no fitted unchanged places"
    run_tstyles -- scene "$SCRATCH/data/ct-phantom.nii" -o "$SCRATCH/off.json" --unchanged off
    expect_exit 0
    grep -q '"unchanged"' "$SCRATCH/off.json" && fail "--unchanged off wrote unchanged places"
    run_tstyles -- scene "$SCRATCH/data/ct-phantom.nii" -o "$SCRATCH/given.json" --unchanged 0.05 \
        --unchanged-opacity 0.3
    expect_exit 0
    grep -q '"below": 0.05' "$SCRATCH/given.json" || fail "--unchanged 0.05 not in the scene"
    grep -q '"opacity": 0.3' "$SCRATCH/given.json" || fail "--unchanged-opacity 0.3 not in the scene"
    run_tstyles -- render "$SCRATCH/given.json" -o "$SCRATCH/given.png" --width 64 --height 64
    expect_exit 0
    run_tstyles -- render "$SCRATCH/data/ct-phantom.nii" -o "$SCRATCH/out.png" --unchanged 2
    expect_exit 2
    expect_stderr_contains "--unchanged: must be in [0, 1], got 2"
    run_tstyles -- render "$SCRATCH/data/ct-phantom.nii" -o "$SCRATCH/out.png" --unchanged-opacity 1.5
    expect_exit 2
    expect_stderr_contains "--unchanged-opacity: must be in [0, 1], got 1.5"
    run_tstyles -- render "$SCRATCH/data/ct-phantom.nii" -o "$SCRATCH/out.png" --tc temporal-average --unchanged 0.1
    expect_exit 2
    expect_stderr_contains "--unchanged: temporal-average does not pick a time-step"
    run_tstyles -- render "$SCRATCH/data/ct-phantom.nii" -o "$SCRATCH/out.png" --unchanged off --unchanged-opacity 0.2
    expect_exit 2
    expect_stderr_contains "--unchanged-opacity: says how unchanged places show, but --unchanged is off"
    expect_no_output "$SCRATCH/out.png"
}

case_bad_aspect_option() {
    write_samples
    run_tstyles -- render "$SCRATCH/data/moving-blob.nii" -o "$SCRATCH/out.png" --aspect squashed
    expect_exit 2
    expect_stderr_contains "--aspect: unknown value \"squashed\""
    expect_no_output "$SCRATCH/out.png"
}

case_mirroring_orientation_refused() {
    write_samples
    run_tstyles -- render "$SCRATCH/data/moving-blob.nii" -o "$SCRATCH/out.png" --orientation +x,+y,-z
    expect_exit 2
    expect_stderr_contains "--orientation: mirrors the data"
    expect_no_output "$SCRATCH/out.png"
}

case_scene_of_a_scene_refused() {
    write_samples
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- scene "$SCRATCH/scene.json" -o "$SCRATCH/again.json"
    expect_exit 2
    expect_error_line "$SCRATCH/scene.json" "" "is a scene file already"
    expect_no_output "$SCRATCH/again.json"
}

# --dataset replaces a scene's dataset; given with a dataset as the input it is a mistake.
case_dataset_option_with_dataset_input() {
    write_samples
    run_tstyles -- render "$SCRATCH/data/moving-blob.nii" --dataset "$SCRATCH/data/ct-phantom.nii" -o "$SCRATCH/out.png"
    expect_exit 2
    expect_stderr_contains "--dataset: replaces a scene file's dataset"
    expect_no_output "$SCRATCH/out.png"
}

# convert keeps what the axes and the times mean: the manifest folder shows the same dates and
# gets the same automatic orientation as the NetCDF file.
case_convert_keeps_meaning() {
    write_samples
    run_tstyles -- convert "$SCRATCH/data/ocean-anomalies.nc" -o "$SCRATCH/ocean"
    expect_exit 0
    run_tstyles -- info "$SCRATCH/ocean"
    expect_exit 0
    expect_stdout_contains "Time: days since 1950-01-01 00:00:00 (noleap calendar)"
    expect_stdout_contains "1969-02"
    expect_stdout_contains "orientation: right = +x (lon, east), up = +z (depth, up), toward the viewer = -y (lat, north)"
}

run_case
