#!/usr/bin/env bash
# End-to-end: `tstyles render` turns a scene into an image file, under each backend and format.
# Usage: render_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

# Renders the 64x64 scene with one backend and checks the PNG and what the command says it used.
render_png_with() {
    local backend=$1 context_name=$2
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --backend "$backend"
    expect_exit 0
    expect_image "$SCRATCH/out.png" 64 64
    expect_stdout_contains "wrote $SCRATCH/out.png (64x64, temporal-mip, $(dataset_step_count "$DATASET") time-steps"
    expect_stdout_contains "$context_name"
}

case_egl_png() { render_png_with egl "EGL"; }
case_osmesa_png() { render_png_with osmesa "OSMesa"; }

# The format follows the extension: render_format EXTENSION OIIO_FORMAT_NAME PIXEL_TYPE_REGEX.
render_format() {
    local extension=$1 format=$2 pixel_type=$3
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.$extension"
    expect_exit 0
    expect_image "$SCRATCH/out.$extension" 64 64
    "$OIIOTOOL" --info "$SCRATCH/out.$extension" | grep -qE "4 channel, $pixel_type $format\$" ||
        fail "out.$extension is not a $pixel_type $format file: $("$OIIOTOOL" --info "$SCRATCH/out.$extension")"
}

case_tiff() { render_format tif tiff uint8; }
# EXR keeps the renderer's 32-bit floats.
case_exr() { render_format exr openexr 'float'; }

case_size_override() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --width 48 --height 32
    expect_exit 0
    expect_image "$SCRATCH/out.png" 48 32
    expect_stdout_contains "(48x32,"
}

# --tc replaces the scene's compositor, and the picture changes with it.
case_tc_average() {
    write_scene "$SCRATCH/scene.json" "$DATASET" '"compositor": "temporal-max-change"'
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/average.png" --tc temporal-average
    expect_exit 0
    expect_image "$SCRATCH/average.png" 64 64
    expect_stdout_contains "(64x64, temporal-average,"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/mip.png" --tc temporal-mip
    expect_exit 0
    expect_stdout_contains "(64x64, temporal-mip,"
    # With the default white TSTF the average of the time-steps is fainter than their maximum.
    if "$OIIOTOOL" "$SCRATCH/average.png" "$SCRATCH/mip.png" --diff >/dev/null 2>&1; then
        fail "temporal-average and temporal-mip gave the same image"
    fi
}

# A step so fine that llvmpipe cuts rays short (it ends a pixel's loops after 65535 passes): the
# image is still written, and the command warns on stderr, naming the scene and how many rays.
# Drivers without that limit take every sample and say nothing.
case_cut_short_rays_warning() {
    write_scene "$SCRATCH/scene.json" "$DATASET" '"raycast": {"step": 0.00003, "termination": 1.0}'
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --width 32 --height 32
    expect_exit 0
    expect_image "$SCRATCH/out.png" 32 32
    if grep -qF llvmpipe "$OUT_FILE"; then
        expect_stderr_contains "warning: $SCRATCH/scene.json: "
        expect_stderr_contains "of the image's rays were cut short by the OpenGL driver's limit on loop passes"
    elif grep -qF "cut short" "$ERR_FILE"; then
        fail "a driver without llvmpipe's loop limit reported rays cut short"
    fi
}

# A relative dataset path starts at the scene file's folder, not at the working directory.
case_relative_dataset() {
    mkdir -p "$SCRATCH/scenes" "$SCRATCH/elsewhere"
    ln -s "$(dirname "$DATASET")" "$SCRATCH/superellipsoid"
    write_scene "$SCRATCH/scenes/scene.json" "../superellipsoid/series.json"
    cd "$SCRATCH/elsewhere" || fail "cannot enter $SCRATCH/elsewhere"
    run_tstyles -- render ../scenes/scene.json -o out.png
    expect_exit 0
    expect_image "$SCRATCH/elsewhere/out.png" 64 64
}

# Rendering again over an existing file replaces it.
case_overwrite() {
    write_scene "$SCRATCH/scene.json"
    echo "not an image" >"$SCRATCH/out.png"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png"
    expect_exit 0
    expect_image "$SCRATCH/out.png" 64 64
}

# Over --max-gpu-memory the series is uploaded coarser (a fifth of its 5 MiB would not even hold
# it at 8 bits) and one line on stderr says so; the image is still written.
case_max_gpu_memory_message() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --max-gpu-memory 1M
    expect_exit 0
    expect_image "$SCRATCH/out.png" 64 64
    expect_stderr_contains "tstyles: $DATASET: GPU memory budget 1.0 MiB (--max-gpu-memory): the series needs 5.0 MiB at full size (16-bit); uploading"
    expect_stderr_contains "resolution 1/"
    [ "$(wc -l <"$ERR_FILE")" -eq 1 ] || fail "expected one line on stderr"
}

# Values 0 .. 255 of a uint8 dataset are exact at 8 bits: half the bytes, the same values.
case_max_gpu_memory_eight_bits() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --max-gpu-memory 3M
    expect_exit 0
    expect_stderr_contains "8-bit densities (every value is stored exactly)"
}

run_case
