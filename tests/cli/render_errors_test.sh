#!/usr/bin/env bash
# End-to-end: `tstyles render` on bad input exits with 2, prints one line naming the file and the
# field, and writes nothing (no image, no temporary file).
# Usage: render_errors_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

OUTPUT="$SCRATCH/out.png"

# Renders SCENE to $OUTPUT and expects a bad-input failure: render_fails SCENE FILE [FIELD] [PROBLEM].
render_fails() {
    local scene=$1
    shift
    run_tstyles -- render "$scene" -o "$OUTPUT"
    expect_exit 2
    expect_error_line "$@"
    expect_no_output "$OUTPUT"
}

case_missing_scene() {
    render_fails "$SCRATCH/no-such-scene.json" "$SCRATCH/no-such-scene.json" "" "cannot open the scene file"
}

case_scene_not_json() {
    printf '{"dataset": "%s",\n  "image": {"width": 64,}\n}\n' "$DATASET" >"$SCRATCH/scene.json"
    render_fails "$SCRATCH/scene.json" "$SCRATCH/scene.json" "" "not valid JSON: parse error at line 2"
}

case_unknown_key() {
    write_scene "$SCRATCH/scene.json" "$DATASET" '"camera": {"orbit": {"azimuth": 30}}'
    render_fails "$SCRATCH/scene.json" "$SCRATCH/scene.json" "camera.orbit.azimuth" "unknown key"
    # The message lists what is allowed, so the typo is easy to fix.
    expect_stderr_contains "azimuth_deg"
}

case_wrong_type() {
    printf '{"dataset": "%s", "image": {"width": "wide", "height": 64}}\n' "$DATASET" >"$SCRATCH/scene.json"
    render_fails "$SCRATCH/scene.json" "$SCRATCH/scene.json" "image.width" "expected a number, got a string"
}

case_out_of_range() {
    write_scene "$SCRATCH/scene.json" "$DATASET" '"raycast": {"termination": 1.5}'
    render_fails "$SCRATCH/scene.json" "$SCRATCH/scene.json" "raycast.termination" "1.5"
}

case_unknown_compositor() {
    write_scene "$SCRATCH/scene.json" "$DATASET" '"compositor": "temporal-median"'
    render_fails "$SCRATCH/scene.json" "$SCRATCH/scene.json" "compositor" 'unknown value "temporal-median"'
}

case_tc_nonsense() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$OUTPUT" --tc nonsense
    expect_exit 2
    # A usage error from the option parser, before any file is read: it names the option, the value
    # and the allowed names.
    expect_stderr_contains '--tc: nonsense not in'
    expect_stderr_contains "temporal-average"
    expect_no_output "$OUTPUT"
}

case_dataset_missing() {
    write_scene "$SCRATCH/scene.json" "$SCRATCH/no-such-dataset/series.json"
    render_fails "$SCRATCH/scene.json" "$SCRATCH/no-such-dataset/series.json" "" "not found"
}

case_dataset_truncated() {
    cp -R "$(dirname "$DATASET")" "$SCRATCH/dataset"
    local raw="$SCRATCH/dataset/t03.raw"
    local size
    size=$(wc -c <"$raw" | tr -d ' ')
    head -c $((size / 2)) "$raw" >"$raw.half" && mv "$raw.half" "$raw"
    write_scene "$SCRATCH/scene.json" "$SCRATCH/dataset/series.json"
    render_fails "$SCRATCH/scene.json" "$SCRATCH/dataset/series.json" "time_steps[3].values.file" \
        "is truncated: expected $size bytes"
    expect_stderr_contains "found $((size / 2)) bytes"
}

# A float32 dataset of two 2x2x2 time-steps, written by hand (docs/dataset-format.md). The values
# of t01.raw are given as 4-byte little-endian octal escapes for printf.
write_float_dataset() {
    local folder=$1 second_step=$2
    mkdir -p "$folder"
    cat >"$folder/series.json" <<'EOF'
{
  "format": "tstyles-series",
  "version": 1,
  "value_range": [0, 1],
  "time_steps": [
    {"time": 0, "grid": {"type": "rectilinear", "dims": [2, 2, 2], "spacing": [0.5, 0.5, 0.5]},
     "values": {"file": "t00.raw", "type": "float32"}},
    {"time": 1, "grid": {"type": "rectilinear", "dims": [2, 2, 2], "spacing": [0.5, 0.5, 0.5]},
     "placement": {"origin": [0.25, 0, 0]},
     "values": {"file": "t01.raw", "type": "float32"}}
  ]
}
EOF
    local zero='\000\000\000\000' one='\000\000\200\077'
    # The variables hold octal escapes, so they belong in the format.
    # shellcheck disable=SC2059
    printf "$zero$one$zero$one$zero$one$zero$one" >"$folder/t00.raw"
    # shellcheck disable=SC2059
    printf "$second_step" >"$folder/t01.raw"
}

# An infinity is never a value; NaN in the same place is a voxel without data and renders.
case_dataset_inf() {
    local zero='\000\000\000\000' one='\000\000\200\077' inf='\000\000\200\177' nan='\000\000\300\177'
    # First the same dataset without the Inf, to show that the hand-written files are valid.
    write_float_dataset "$SCRATCH/valid" "$one$zero$one$zero$one$zero$one$zero"
    run_tstyles -- info "$SCRATCH/valid/series.json"
    expect_exit 0
    expect_stdout_contains "float32"
    # Voxel index 5 is (x, y, z) = (1, 0, 1): index = x + 2 * (y + 2 * z).
    write_float_dataset "$SCRATCH/inf" "$one$zero$one$zero$one$inf$one$zero"
    write_scene "$SCRATCH/scene.json" "$SCRATCH/inf/series.json"
    render_fails "$SCRATCH/scene.json" "$SCRATCH/inf/series.json" "time_steps[1].values.file" "non-finite value (Inf)"
    expect_stderr_contains "(x, y, z) = (1, 0, 1)"
    write_float_dataset "$SCRATCH/nan" "$one$zero$one$zero$one$nan$one$zero"
    run_tstyles -- info "$SCRATCH/nan/series.json"
    expect_exit 0
    expect_stdout_contains "Missing values: 1 voxels without data (6.2 %)"
}

# A beam grid whose azimuths 0 and 0.0001 degrees lie closer than the renderer's loop-free beam
# lookup can tell apart (at most 65536 buckets over the fan's 80 degrees): `info` reads it, `render`
# refuses it, naming the manifest and the field (docs/dataset-format.md).
case_beam_angles_too_close() {
    mkdir -p "$SCRATCH/fan"
    cat >"$SCRATCH/fan/series.json" <<'EOF'
{
  "format": "tstyles-series",
  "version": 1,
  "value_range": [0, 255],
  "time_steps": [
    {"time": 0,
     "grid": {"type": "beam", "dims": [4, 2, 3], "azimuth_angles_deg": [-40, 0, 0.0001, 40],
              "elevation_deg": [-10, 10], "range": [1, 2]},
     "values": {"file": "t00.raw", "type": "uint8"}}
  ]
}
EOF
    head -c 24 /dev/zero >"$SCRATCH/fan/t00.raw"
    run_tstyles -- info "$SCRATCH/fan/series.json"
    expect_exit 0
    write_scene "$SCRATCH/scene.json" "$SCRATCH/fan/series.json"
    render_fails "$SCRATCH/scene.json" "$SCRATCH/fan/series.json" "time_steps[0].grid.azimuth_angles_deg" \
        "neighbouring beams are too close together"
}

case_output_unsupported_extension() {
    write_scene "$SCRATCH/scene.json"
    OUTPUT="$SCRATCH/out.xyz"
    render_fails "$SCRATCH/scene.json" "$SCRATCH/out.xyz" "" "cannot write images of this type"
}

case_output_folder_missing() {
    write_scene "$SCRATCH/scene.json"
    OUTPUT="$SCRATCH/no-such-folder/out.png"
    render_fails "$SCRATCH/scene.json" "$OUTPUT" "" "does not exist"
    [ ! -e "$SCRATCH/no-such-folder" ] || fail "the missing output folder was created"
}

# An output path that is a folder: the finished temporary file cannot be renamed onto it.
case_output_is_folder() {
    write_scene "$SCRATCH/scene.json"
    mkdir -p "$SCRATCH/taken.png"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/taken.png"
    expect_exit 2
    expect_error_line "$SCRATCH/taken.png"
    [ -d "$SCRATCH/taken.png" ] || fail "the folder in the way was replaced"
    local leftovers
    leftovers=$(find "$SCRATCH" -maxdepth 1 -name '.*.tmp*')
    [ -z "$leftovers" ] || fail "temporary files left behind: $leftovers"
}

# A bad budget is a usage error naming the option, before any file is read.
case_max_gpu_memory_zero() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$OUTPUT" --max-gpu-memory 0
    expect_exit 2
    expect_error_line "--max-gpu-memory" "" 'size out of range: "0"'
    expect_no_output "$OUTPUT"
}

case_max_gpu_memory_not_a_size() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$OUTPUT" --max-gpu-memory abc
    expect_exit 2
    expect_error_line "--max-gpu-memory" "" 'expected a size such as 512M, 2G or 800000 (bytes), got "abc"'
    expect_no_output "$OUTPUT"
    run_tstyles -- info "$DATASET" --max-gpu-memory abc
    expect_exit 2
    expect_error_line "--max-gpu-memory" "" "abc"
}

run_case
