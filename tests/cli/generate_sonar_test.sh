#!/usr/bin/env bash
# End-to-end: tools/generate_sonar writes the same bytes on every run, and rejects bad flags and an
# unwritable output with exit code 2 and nothing half-written.
# Usage: generate_sonar_test.sh GENERATE_SONAR SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh;
# the generator stands where the library expects tstyles).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

# Two runs into two folders: every file has the same SHA-256 (and the same file names).
case_same_bytes_twice() {
    run_tstyles -- --output "$SCRATCH/first" --pings 2
    expect_exit 0
    expect_stdout_contains "wrote 2 pings"
    run_tstyles -- --output "$SCRATCH/second" --pings 2
    expect_exit 0
    local first second
    first=$(cd "$SCRATCH/first" && sha256sum ./* | sort)
    second=$(cd "$SCRATCH/second" && sha256sum ./* | sort)
    [ "$first" = "$second" ] || fail "the two runs differ: $first VS $second"
    [ "$(echo "$first" | wc -l)" -eq 5 ] || fail "expected series.json and 2 value and 2 mask files: $first"
}

case_too_many_pings() {
    run_tstyles -- --output "$SCRATCH/out" --pings 76
    expect_exit 2
    expect_stderr_contains "--pings"
    [ ! -e "$SCRATCH/out" ] || fail "the rejected run created its output folder"
}

case_output_is_file() {
    touch "$SCRATCH/taken"
    run_tstyles -- --output "$SCRATCH/taken" --pings 1
    expect_exit 2
    expect_stderr_contains "generate_sonar: "
    expect_stderr_contains "taken"
    [ -f "$SCRATCH/taken" ] && [ ! -s "$SCRATCH/taken" ] || fail "the file in the way was changed"
}

"case_$CASE"
