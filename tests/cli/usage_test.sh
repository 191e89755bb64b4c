#!/usr/bin/env bash
# End-to-end: command-line mistakes are CLI11 usage errors with exit code 2; --help exits with 0.
# Usage: usage_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

case_help() {
    run_tstyles -- --help
    expect_exit 0
    expect_stdout_contains "render"
    expect_stdout_contains "info"
}

case_no_subcommand() {
    run_tstyles --
    expect_exit 2
    expect_stderr_contains "subcommand"
    expect_stderr_contains "--help"
}

case_unknown_subcommand() {
    run_tstyles -- paint "$SCRATCH/scene.json"
    expect_exit 2
    # CLI11 checks for a subcommand before it complains about the extra argument.
    expect_stderr_contains "A subcommand is required"
}

case_unknown_flag() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --colour red
    expect_exit 2
    expect_stderr_contains "--colour"
    expect_no_output "$SCRATCH/out.png"
}

case_missing_output_flag() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json"
    expect_exit 2
    expect_stderr_contains "--output"
}

case_bad_backend() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --backend vulkan
    expect_exit 2
    expect_stderr_contains "vulkan"
    expect_no_output "$SCRATCH/out.png"
}

case_width_out_of_range() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/out.png" --width 0
    expect_exit 2
    expect_stderr_contains "--width"
    expect_no_output "$SCRATCH/out.png"
}

run_case
