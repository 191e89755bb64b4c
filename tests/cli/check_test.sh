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
    cp "$SCRATCH/golden/first.png" "$SCRATCH/first-before.png"
    # Only `first` is rewritten (second wrote the shared golden last, so it changes back); third's
    # golden keeps its bytes. Every case compares with the goldens as the run found them: all pass.
    run_tstyles -- check "$SCRATCH/suite.json" --update first --report "$SCRATCH/report"
    expect_exit 0
    expect_stdout_contains "golden rewritten; it changed by max delta"
    ! cmp -s "$SCRATCH/golden/first.png" "$SCRATCH/first-before.png" || fail "first.png was not rewritten"
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


# --jobs 1 and --jobs 3 on one backend: the same exit code, table, report and images, whatever
# order the cases finished in.
jobs_agree() {
    local backend=$1
    write_suite
    run_tstyles -- check "$SCRATCH/suite.json" --update first --jobs 2 --backend "$backend" --report "$SCRATCH/report"
    expect_stdout_contains "2 parallel cases (--jobs 2)"
    for jobs in 1 3; do
        run_tstyles -- check "$SCRATCH/suite.json" --jobs "$jobs" --backend "$backend" --report "$SCRATCH/report-$jobs"
        expect_exit 1
        cp "$OUT_FILE" "$SCRATCH/stdout-$jobs.txt"
        [ "$(grep -c '^\[[1-3]/3\] [a-z]*: ' "$OUT_FILE")" = 3 ] || fail "not one progress line per case"
    done
    head -n 1 "$SCRATCH/stdout-1.txt" | grep -qx "1 case at a time (--jobs 1)" || fail "first line with --jobs 1"
    head -n 1 "$SCRATCH/stdout-3.txt" | grep -qx "3 parallel cases (--jobs 3)" || fail "first line with --jobs 3"
    diff <(table_of "$SCRATCH/stdout-1.txt") <(table_of "$SCRATCH/stdout-3.txt") >&2 ||
        fail "the tables of --jobs 1 and --jobs 3 differ"
    grep -q "^\[2/3\] second  *FAIL" <(table_of "$SCRATCH/stdout-3.txt") || fail "the table is not in suite order"
    diff <(junit_without_times "$SCRATCH/report-1/junit.xml") <(junit_without_times "$SCRATCH/report-3/junit.xml") >&2 ||
        fail "junit.xml of --jobs 1 and --jobs 3 differ"
    diff -r "$SCRATCH/report-1" "$SCRATCH/report-3" -x junit.xml >&2 ||
        fail "the reports (index.html, images) of --jobs 1 and --jobs 3 differ"
}
case_jobs_agree_egl() { jobs_agree egl; }
case_jobs_agree_osmesa() { jobs_agree osmesa; }

# --update with cases rendered at once writes the same goldens as one at a time.
case_update_with_jobs() {
    write_suite golden/second.png
    run_tstyles -- check "$SCRATCH/suite.json" --update --all --jobs 1 --report "$SCRATCH/report"
    expect_exit 0
    mv "$SCRATCH/golden" "$SCRATCH/golden-1"
    mkdir "$SCRATCH/golden"
    run_tstyles -- check "$SCRATCH/suite.json" --update --all --jobs 3 --report "$SCRATCH/report"
    expect_exit 0
    expect_stdout_contains "new golden"
    diff -r "$SCRATCH/golden-1" "$SCRATCH/golden" >&2 || fail "--jobs 3 wrote other goldens than --jobs 1"
    run_tstyles -- check "$SCRATCH/suite.json" --jobs 2 --report "$SCRATCH/report"
    expect_exit 0
    expect_stdout_contains "all 3 cases pass"
}

# --jobs auto: one case at a time on a software rasteriser, else up to 4; the first line says which.
case_jobs_auto() {
    write_suite
    run_tstyles -- check "$SCRATCH/suite.json" --report "$SCRATCH/report"
    expect_exit 1
    local first
    first=$(head -n 1 "$OUT_FILE")
    if grep -q "llvmpipe" <(tail -n 1 "$OUT_FILE"); then
        [ "$first" = "1 case at a time: llvmpipe already uses every core (--jobs N overrides)" ] ||
            fail "auto on llvmpipe chose: $first"
    else
        grep -qE "^([1-3] parallel cases|1 case at a time) \(auto" <<<"$first" || fail "auto chose: $first"
    fi
}

bad_jobs() {
    write_suite
    run_tstyles -- check "$SCRATCH/suite.json" --jobs "$1" --report "$SCRATCH/report"
    expect_exit 2
    expect_stderr_contains "--jobs: is \"$1\"; expected a whole number"
    [ ! -e "$SCRATCH/report" ] || fail "a report was written for --jobs $1"
}
case_jobs_zero() { bad_jobs 0; }
case_jobs_not_a_number() { bad_jobs x; }

# A case that fails to render (its dataset does not exist) stops the run with exit 2 and the
# message that one case at a time gives, whatever the other threads were doing; no report.
case_bad_case_with_jobs() {
    write_suite
    sed 's|"dataset": "[^"]*"|"dataset": "nowhere/series.json"|' "$SCENES/figure1-focus-step6.json" >"$SCRATCH/bad.json"
    sed -i "s|\"scene\": \"$SCENES/figure1-focus-step6.json\"|\"scene\": \"$SCRATCH/bad.json\"|" "$SCRATCH/suite.json"
    grep -q bad.json "$SCRATCH/suite.json" || fail "the test did not write its bad suite"
    for jobs in 1 2; do
        run_tstyles -- check "$SCRATCH/suite.json" --jobs "$jobs" --report "$SCRATCH/report"
        expect_exit 2
        expect_stderr_contains "nowhere/series.json"
        [ ! -e "$SCRATCH/report" ] || fail "a report was written after a bad case (--jobs $jobs)"
        grep -v '^+ ' "$ERR_FILE" >"$SCRATCH/stderr-$jobs.txt"
    done
    diff "$SCRATCH/stderr-1.txt" "$SCRATCH/stderr-2.txt" >&2 || fail "--jobs 2 reports another error than --jobs 1"
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
case_bad_renderer_thresholds() {
    local scene="{\"scene\": \"$SCENES/figure1-focus-step3.json\"}"
    bad_suite "{\"renderer_thresholds\": {\"llvmpipe\": {}}, \"cases\": [$scene]}" \
        "renderer_thresholds: expected an array"
    bad_suite "{\"renderer_thresholds\": [{\"thresholds\": {}}], \"cases\": [$scene]}" \
        "renderer_thresholds[0].renderer: missing"
    bad_suite "{\"renderer_thresholds\": [{\"renderer\": \"llvmpipe\", \"thresholds\": {\"max_mean\": -1}}], \"cases\": [$scene]}" \
        "renderer_thresholds[0].thresholds.max_mean: must be >= 0"
}

# A case renders the same pixels whatever was rendered before it: the styled Figure 1 (focus on
# step 6) after another styled scene of its dataset, and alone, to the bit. (While the renderer
# took the gradient atlas from a series' second styled frame on, the two differed by 1/255.)
case_order_does_not_change_pixels() {
    local after="$SCRATCH/after.json" alone="$SCRATCH/alone.json"
    local styled3="{\"name\": \"styled3\", \"scene\": \"$SCENES/figure1-styled-focus-step3.json\", \"golden\": \"golden/styled3.png\", \"width\": 96, \"height\": 96}"
    local styled6="{\"name\": \"styled6\", \"scene\": \"$SCENES/figure1-styled-focus-step6.json\", \"golden\": \"golden/styled6.png\", \"width\": 96, \"height\": 96}"
    local exact='"thresholds": {"max_difference": 0, "pixel_threshold": 0, "max_failing_share": 0, "max_mean": 0}'
    printf '{%s, "cases": [%s, %s]}\n' "$exact" "$styled3" "$styled6" >"$after"
    printf '{%s, "cases": [%s]}\n' "$exact" "$styled6" >"$alone"
    mkdir -p "$SCRATCH/golden"
    run_tstyles -- check "$after" --update --all --jobs 1 --report "$SCRATCH/report"
    expect_exit 0
    run_tstyles -- check "$alone" --report "$SCRATCH/report"
    expect_exit 0
    expect_stdout_contains "max 0/255"
}

# A golden 3/255 brighter all over than the render: within the suite's loose thresholds, beyond the
# exact ones of a renderer entry that names this driver (OSMesa is llvmpipe), and within them again
# where the entry names another renderer.
case_renderer_thresholds() {
    local scene="$SCENES/figure1-focus-step3.json"
    write_renderer_suite() {
        cat >"$SCRATCH/suite.json" <<JSON
{
  "thresholds": {"pixel_threshold": 6, "max_failing_share": 1, "max_mean": 5, "max_difference": 255, "min_ssim": 0},
  "renderer_thresholds": [{"renderer": "$1", "thresholds": {"max_difference": 0}}],
  "cases": [{"name": "focus", "scene": "$scene", "golden": "golden.png", "width": 64, "height": 64}]
}
JSON
    }
    write_renderer_suite llvmpipe
    run_tstyles -- check "$SCRATCH/suite.json" --update --all --backend osmesa --report "$SCRATCH/report"
    expect_exit 0
    "$OIIOTOOL" "$SCRATCH/golden.png" --addc 0.012 -o "$SCRATCH/golden.png" || fail "oiiotool could not brighten the golden"
    run_tstyles -- check "$SCRATCH/suite.json" --backend osmesa --report "$SCRATCH/report"
    expect_exit 1
    expect_stdout_contains "thresholds: the suite's renderer_thresholds for \"llvmpipe\""
    expect_stdout_contains "max delta 3/255 > 0/255"
    write_renderer_suite "no such renderer"
    run_tstyles -- check "$SCRATCH/suite.json" --backend osmesa --report "$SCRATCH/report"
    expect_exit 0
    expect_stdout_contains "all 1 cases pass"
    ! grep -qF "thresholds: the suite's" "$OUT_FILE" || fail "the suite's own thresholds applied, but stdout names an entry"
}

run_case
