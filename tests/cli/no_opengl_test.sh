#!/usr/bin/env bash
# End-to-end: without a usable OpenGL 4.5 core context `tstyles render` exits with 3, says what it
# tried, and writes nothing.
# Usage: no_opengl_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
#
# How the context is taken away (checked with Mesa 22.3 and libglvnd 1.6):
# - MESA_GL_VERSION_OVERRIDE=3.3 caps every Mesa driver (OSMesa, and EGL on Mesa) at OpenGL 3.3, so
#   a 4.5 core context cannot be created: a clean failure, unlike GALLIUM_DRIVER=nonexistent, which
#   crashes inside libOSMesa.
# - __EGL_VENDOR_LIBRARY_FILENAMES naming a file that does not exist leaves libglvnd with no EGL
#   vendor at all, which also covers a vendor that ignores Mesa's variables (NVIDIA).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

NO_MESA_GL45="MESA_GL_VERSION_OVERRIDE=3.3"
NO_EGL_VENDOR="__EGL_VENDOR_LIBRARY_FILENAMES=$SCRATCH/no-such-vendor.json"

# render_without_gl BACKEND TRIED... : exit 3, the backend named, each of TRIED listed, no file.
render_without_gl() {
    local backend=$1
    shift
    write_scene "$SCRATCH/scene.json"
    run_tstyles "$NO_MESA_GL45" "$NO_EGL_VENDOR" -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" \
        --backend "$backend"
    expect_exit 3
    expect_stderr_contains "tstyles: no usable OpenGL 4.5 core context (backend $backend)"
    local tried
    for tried in "$@"; do expect_stderr_contains "  $tried: "; done
    expect_no_output "$SCRATCH/out.png"
}

case_osmesa() { render_without_gl osmesa "OSMesa"; }
case_egl() { render_without_gl egl "EGL"; }
# Auto tries EGL, then OSMesa, and reports both.
case_auto() { render_without_gl auto "EGL" "OSMesa"; }

# Bad input is reported before the missing OpenGL: exit 2, not 3.
case_bad_scene_first() {
    write_scene "$SCRATCH/scene.json" "$DATASET" '"compositor": "temporal-median"'
    run_tstyles "$NO_MESA_GL45" "$NO_EGL_VENDOR" -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png"
    expect_exit 2
    expect_error_line "$SCRATCH/scene.json" "compositor"
}

run_case
