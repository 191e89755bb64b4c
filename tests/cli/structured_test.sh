#!/usr/bin/env bash
# End-to-end: structured (curvilinear) grids and Plot3D files through `tstyles info` and `render`;
# bad grids and bad Plot3D files end in exit code 2 and one line naming the file and the problem.
# Usage: structured_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

# The generator is built beside tstyles, under tools/.
GENERATOR="$(dirname "$TSTYLES")/tools/generate_warped_box"

warped_series() {
    "$GENERATOR" --output "$SCRATCH/warped" --steps 3 >/dev/null || fail "generate_warped_box failed"
}

warped_plot3d() {
    "$GENERATOR" --plot3d --output "$SCRATCH/plot3d" --steps 3 >/dev/null || fail "generate_warped_box --plot3d failed"
    SOLUTIONS="$SCRATCH/plot3d/flow00.q,$SCRATCH/plot3d/flow01.q,$SCRATCH/plot3d/flow02.q"
}

case_info_manifest() {
    warped_series
    run_tstyles -- info "$SCRATCH/warped"
    expect_exit 0
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "structured 33x33x17"
    expect_stdout_contains "inverse map 65x65x33 (2.13 MiB)"
}

case_info_plot3d() {
    warped_plot3d
    run_tstyles -- info "$SCRATCH/plot3d/grid.xyz" --solution "$SOLUTIONS" --var pressure
    expect_exit 0
    expect_stdout_contains "Series: grid (pressure)"
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "structured 33x33x17"
}

case_render_manifest() {
    warped_series
    write_scene "$SCRATCH/scene.json" "$SCRATCH/warped/series.json" \
        '"stf": {"opacity": [{"at": 0.2, "opacity": 0.0}, {"at": 0.5, "opacity": 0.8}], "color": [{"at": 0, "color": [1, 0.5, 0]}]}'
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --backend osmesa
    expect_exit 0
    expect_image "$SCRATCH/out.png" 64 64
}

case_render_plot3d() {
    warped_plot3d
    write_scene "$SCRATCH/scene.json" "$SCRATCH/plot3d/grid.xyz" \
        '"stf": {"opacity": [{"at": 0.2, "opacity": 0.0}, {"at": 0.5, "opacity": 0.8}], "color": [{"at": 0, "color": [0, 0.5, 1]}]}'
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --backend osmesa --solution "$SOLUTIONS" \
        --var momentum-magnitude
    expect_exit 0
    expect_image "$SCRATCH/out.png" 64 64
}

# Without a Plot3D extension the content decides: a binary file is read as a Plot3D grid.
case_plot3d_by_content() {
    warped_plot3d
    mv "$SCRATCH/plot3d/grid.xyz" "$SCRATCH/plot3d/mesh.bin"
    run_tstyles -- info "$SCRATCH/plot3d/mesh.bin" --solution "$SOLUTIONS"
    expect_exit 0
    expect_stdout_contains "structured 33x33x17"
    run_tstyles -- info "$SCRATCH/plot3d/mesh.bin"
    expect_exit 2
    expect_error_line "$SCRATCH/plot3d/mesh.bin" "--solution" "needs at least one solution (q) file"
}

case_plot3d_truncated() {
    warped_plot3d
    truncate -s 1000 "$SCRATCH/plot3d/grid.xyz"
    run_tstyles -- info "$SCRATCH/plot3d/grid.xyz" --solution "$SOLUTIONS"
    expect_exit 2
    expect_error_line "$SCRATCH/plot3d/grid.xyz" "" "Plot3D grid file is truncated"
}

case_plot3d_without_solution() {
    warped_plot3d
    run_tstyles -- info "$SCRATCH/plot3d/grid.xyz"
    expect_exit 2
    expect_error_line "$SCRATCH/plot3d/grid.xyz" "--solution" "needs at least one solution (q) file"
}

case_plot3d_render_error_writes_nothing() {
    warped_plot3d
    truncate -s 1000 "$SCRATCH/plot3d/flow01.q"
    write_scene "$SCRATCH/scene.json" "$SCRATCH/plot3d/grid.xyz"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --backend osmesa --solution "$SOLUTIONS"
    expect_exit 2
    expect_error_line "$SCRATCH/plot3d/flow01.q" "" "Plot3D solution file is truncated"
    expect_no_output "$SCRATCH/out.png"
}

case_coordinates_truncated() {
    warped_series
    truncate -s 100 "$SCRATCH/warped/grid00.xyz.f32"
    run_tstyles -- info "$SCRATCH/warped"
    expect_exit 2
    expect_error_line "$SCRATCH/warped/series.json" "time_steps[0].grid.coordinates.file" "of time-step 0 is truncated"
}

run_case
