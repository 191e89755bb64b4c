#!/usr/bin/env bash
# End-to-end: `tstyles check` on a small suite of 64x64 scenes: passing, failing and missing-golden
# cases, the report (JUnit XML, HTML, images), --update of named cases only, and bad suites.
# Usage: check_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

SCENES="$SOURCE_DIR/data/scenes"

# A suite of three cases; `second` is checked against the golden of `first` (a different picture)
# unless another golden is given: write_suite [SECOND_GOLDEN].
write_suite() {
    local second_golden=${1:-golden/first.png}
    mkdir -p "$SCRATCH/golden"
    cat >"$SCRATCH/suite.json" <<JSON
{
  "thresholds": {"max_difference": 2},
  "cases": [
    {"name": "first", "scene": "$SCENES/figure1-focus-step3.json", "golden": "golden/first.png", "width": 64, "height": 64},
    {"name": "second", "scene": "$SCENES/figure1-focus-step6.json", "golden": "$second_golden", "width": 64, "height": 64},
    {"name": "third", "scene": "$SCENES/figure4-temporal-mip.json", "golden": "golden/third.png", "width": 64, "height": 64}
  ]
}
JSON
}

case_pass_fail_and_missing() {
    write_suite
    run_tstyles -- check "$SCRATCH/suite.json" --update first --report "$SCRATCH/report"
    expect_exit 1  # third has no golden yet
    expect_image "$SCRATCH/golden/first.png" 64 64
    run_tstyles -- check "$SCRATCH/suite.json" --report "$SCRATCH/report"
    expect_exit 1
    expect_stdout_contains "[1/3] first"
    expect_stdout_contains "2 of 3 cases fail"
    local junit="$SCRATCH/report/junit.xml"
    grep -q '<testsuite name="suite" tests="3" failures="1" errors="1"' "$junit" || fail "junit.xml counts: $(cat "$junit")"
    grep -q '<testcase classname="suite" name="first" time="[0-9.e-]*"/>' "$junit" || fail "first did not pass in junit.xml"
    grep -q '<testcase classname="suite" name="second".*' "$junit" && grep -q '<failure message=".*" type="ImageMismatch">' "$junit" ||
        fail "second is not a failure in junit.xml"
    grep -q '<error message="no golden image at .*third.png' "$junit" || fail "third is not an error in junit.xml"
    for kind in expected actual diff; do
        grep -q "img src=\"second.$kind.png\"" "$SCRATCH/report/index.html" || fail "index.html lacks second.$kind.png"
        expect_image "$SCRATCH/report/second.$kind.png" 64 64
    done
}

case_update_named_only() {
    write_suite
    run_tstyles -- check "$SCRATCH/suite.json" --update --all --report "$SCRATCH/report"
    expect_exit 0
    expect_stdout_contains "new golden"
    cp "$SCRATCH/golden/third.png" "$SCRATCH/third-before.png"
    # Only `first` is rewritten (second wrote the shared golden last, so it changes back); third's
    # golden keeps its bytes.
    run_tstyles -- check "$SCRATCH/suite.json" --update first --report "$SCRATCH/report"
    expect_stdout_contains "golden rewritten; it changed by max delta"
    cmp -s "$SCRATCH/golden/third.png" "$SCRATCH/third-before.png" || fail "third.png changed without --update third"
    run_tstyles -- check "$SCRATCH/suite.json" --update nosuch --report "$SCRATCH/report"
    expect_exit 2
    expect_stderr_contains "suite.json: --update: the suite has no case named \"nosuch\""
}

case_all_pass() {
    write_suite golden/second.png
    run_tstyles -- check "$SCRATCH/suite.json" --update --all --report "$SCRATCH/report"
    expect_exit 0
    # Rendered again (the same driver gives the same bits), every case passes.
    run_tstyles -- check "$SCRATCH/suite.json" --report "$SCRATCH/report"
    expect_exit 0
    expect_stdout_contains "all 3 cases pass"
    grep -q 'tests="3" failures="0" errors="0"' "$SCRATCH/report/junit.xml" || fail "junit.xml: $(cat "$SCRATCH/report/junit.xml")"
}

# What docs/ci.md promises: one driver renders the same bytes run after run, and EGL and OSMesa
# (both llvmpipe here) agree within compare's default thresholds.
case_deterministic_renders() {
    local scene="$SCENES/figure1-styled-focus-step3.json"
    for run in 1 2; do
        run_tstyles -- render "$scene" --width 96 --height 96 --backend egl -o "$SCRATCH/egl-$run.exr"
        expect_exit 0
    done
    # Float pixels compared exactly (the files' metadata holds a time stamp, so not their bytes).
    "$OIIOTOOL" --fail 0 --failpercent 0 --diff "$SCRATCH/egl-1.exr" "$SCRATCH/egl-2.exr" >"$SCRATCH/diff.txt" ||
        fail "two EGL renders of one scene differ: $(cat "$SCRATCH/diff.txt")"
    run_tstyles -- render "$scene" --width 96 --height 96 --backend osmesa -o "$SCRATCH/osmesa.exr"
    expect_exit 0
    run_tstyles -- compare "$SCRATCH/egl-1.exr" "$SCRATCH/osmesa.exr"
    expect_exit 0
}

bad_suite() {
    local body=$1 expected=$2
    printf '%s\n' "$body" >"$SCRATCH/suite.json"
    run_tstyles -- check "$SCRATCH/suite.json" --report "$SCRATCH/report"
    expect_exit 2
    expect_stderr_contains "$SCRATCH/suite.json: $expected"
    [ ! -e "$SCRATCH/report" ] || fail "a report was written for a bad suite"
}

case_unknown_key() {
    bad_suite "{\"cases\": [{\"scene\": \"$SCENES/figure1-focus-step3.json\", \"tolerance\": 3}]}" \
        "cases[0].tolerance: unknown key"
}
case_missing_scene() {
    bad_suite '{"cases": [{"scene": "nowhere.json"}]}' "cases[0].scene: no such scene file"
}
case_bad_threshold() {
    bad_suite "{\"thresholds\": {\"min_ssim\": \"high\"}, \"cases\": [{\"scene\": \"$SCENES/figure1-focus-step3.json\"}]}" \
        "thresholds.min_ssim: expected a number"
}

run_case
