#!/usr/bin/env bash
# End-to-end: the ray modes from the command line. `render --help` lists every one, each renders
# through --ray, its options are read as the scene's keys are (exit 2 naming the option), pairs of
# compositor and mode that mean nothing are refused, `scene` writes the mode, and the sort-last
# distributed render refuses the modes it cannot merge.
# Usage: ray_modes_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

OUTPUT="$SCRATCH/out.png"
MODES="composite maximum minimum average additive attenuated-maximum isosurface"
FIGURE4="$SOURCE_DIR/data/scenes/figure4-temporal-mip.json"

case_help_lists_every_mode() {
    run_tstyles -- render --help
    expect_exit 0
    for name in $MODES; do expect_stdout_contains "  $name: "; done
    expect_stdout_contains "--ray-values"
    expect_stdout_contains "--ray-attenuation"
}

case_every_mode_renders() {
    for name in $MODES; do
        run_tstyles -- render "$FIGURE4" --ray "$name" --width 48 --height 48 -o "$SCRATCH/$name.png"
        expect_exit 0
        expect_image "$SCRATCH/$name.png" 48 48
    done
    # Each mode draws another picture of the same scene.
    local name other
    for name in maximum average isosurface; do
        for other in composite minimum additive; do
            cmp -s "$SCRATCH/$name.png" "$SCRATCH/$other.png" && fail "$name and $other drew the same picture"
        done
    done
    return 0
}

case_options_read_as_keys() {
    run_tstyles -- render "$FIGURE4" --ray isosurface --ray-values 0.3,0.6 --ray-opacities 0.4,1 \
        --width 32 --height 32 -o "$SCRATCH/iso.png"
    expect_exit 0
    expect_image "$SCRATCH/iso.png" 32 32
    run_tstyles -- render "$FIGURE4" --ray isosurface --ray-values 0.3,0.6 --ray-opacities 0.4 -o "$OUTPUT"
    expect_exit 2
    expect_stderr_contains "--ray-opacities: has 1 entries, one for each of the 2 values"
    expect_no_output "$OUTPUT"
    run_tstyles -- render "$FIGURE4" --ray maximum --ray-values 0.3 -o "$OUTPUT"
    expect_exit 2
    expect_stderr_contains "--ray-values: maximum takes no values"
    run_tstyles -- render "$FIGURE4" --ray attenuated-maximum --ray-attenuation 11 -o "$OUTPUT"
    expect_exit 2
    expect_stderr_contains "--ray-attenuation"
    run_tstyles -- render "$FIGURE4" --ray brightest -o "$OUTPUT"
    expect_exit 2
    expect_stderr_contains "--ray: brightest not in"
}

case_pair_without_meaning_refused() {
    run_tstyles -- render "$FIGURE4" --tc temporal-average --ray maximum -o "$OUTPUT"
    expect_exit 2
    expect_stderr_contains "ray.mode: maximum compares a value along the ray"
    expect_no_output "$OUTPUT"
    run_tstyles -- render "$FIGURE4" --tc temporal-average --ray average --width 32 --height 32 -o "$OUTPUT"
    expect_exit 0
}

case_scene_writes_the_mode() {
    run_tstyles -- scene "$DATASET" --ray isosurface --ray-values 0.4 -o "$SCRATCH/iso.json"
    expect_exit 0
    grep -q '"mode": "isosurface"' "$SCRATCH/iso.json" || fail "the scene has no isosurface ray"
    grep -q '"values"' "$SCRATCH/iso.json" || fail "the scene has no iso-values"
    run_tstyles -- render "$SCRATCH/iso.json" --width 32 --height 32 -o "$OUTPUT"
    expect_exit 0
    expect_image "$OUTPUT" 32 32
}

case_distributed_refuses_modes_it_cannot_merge() {
    run_tstyles -- render "$FIGURE4" --ray maximum --distributed -o "$OUTPUT"
    expect_exit 2
    expect_stderr_contains "holds for the composite ray mode only"
    expect_no_output "$OUTPUT"
}

case_bench_measures_each_mode() {
    run_tstyles -- bench --sizes 24 --frames 1 --warmup 0 --datasets superellipsoid --ray composite maximum \
        --json "$SCRATCH/bench.json"
    expect_exit 0
    grep -qE "^superellipsoid +temporal-mip\+maximum +10 +24x24 " "$OUT_FILE" || fail "no row for the maximum"
    grep -qE "^superellipsoid +temporal-mip +10 +24x24 " "$OUT_FILE" || fail "no row for composite"
    # temporal-average composites the time-steps: its maximum is left out, said so.
    expect_stderr_contains "note: skipping temporal-average with ray maximum"
    grep -q '"ray": "maximum"' "$SCRATCH/bench.json" || fail "the JSON does not name the ray mode"
}

# `view --ray`: the window opens the dataset's automatic scene in the mode asked for, and a scene
# saved from it holds the mode and its options.
case_view_with_a_mode() {
    have_xvfb || return 0
    view_and_screenshot "$DATASET" --size 400x300 --ray isosurface --ray-values 0.4,0.7
    grep -q '"mode": "isosurface"' "$SCRATCH/saved.json" || fail "the saved scene has no isosurface ray"
    grep -qE '"values": \[0.4, ?0.7\]' "$SCRATCH/saved.json" || fail "the saved scene lost the iso-values"
}

run_case
