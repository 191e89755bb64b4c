#!/usr/bin/env bash
# End-to-end: the temporal compositors from the command line. `render --help` lists every one, each
# renders through --tc, options and the scene's own code are checked on input (exit 2, one line
# naming the scene file and the field or the line of the code), and the example of
# examples/compositors renders the same image as the built-in it reproduces.
# Usage: compositors_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

OUTPUT="$SCRATCH/out.png"
SCENE="$SCRATCH/scene.json"
COMPOSITORS="temporal-mip temporal-average temporal-max-change temporal-min temporal-std-dev time-of-max
first-arrival last-above threshold-crossing linear-trend chronovolume difference"
# The bundled Figure 4 scene: an STF that shows the super-ellipsoid, an index TSTF over time.
FIGURE4="$SOURCE_DIR/data/scenes/figure4-temporal-mip.json"

# A scene on the bundled dataset whose "compositor" is COMPOSITOR_JSON: compositor_scene COMPOSITOR_JSON.
compositor_scene() {
    write_scene "$SCENE" "$DATASET" "\"compositor\": $1"
}

# The scene's own code CODE (with \n for new lines) inline: custom_scene CODE.
custom_scene() {
    compositor_scene "{\"glsl\": \"$1\", \"reads\": \"index-tstf\"}"
}

# Renders $SCENE and expects a bad-input failure: render_fails FIELD PROBLEM.
render_fails() {
    run_tstyles -- render "$SCENE" -o "$OUTPUT"
    expect_exit 2
    expect_error_line "$SCENE" "$1" "$2"
    expect_no_output "$OUTPUT"
}

case_help_lists_every_compositor() {
    run_tstyles -- render --help
    expect_exit 0
    for name in $COMPOSITORS; do expect_stdout_contains "  $name: "; done
}

case_every_compositor_renders() {
    for name in $COMPOSITORS; do
        # The difference of the first and last time-steps is empty here (their grids do not meet);
        # that of two neighbours, which overlap, is rendered after the loop.
        run_tstyles -- render "$FIGURE4" --tc "$name" --width 48 --height 48 -o "$SCRATCH/$name.png"
        expect_exit 0
        expect_stdout_contains "$name, 10 time-steps"
        [ "$name" = difference ] || expect_image "$SCRATCH/$name.png" 48 48
    done
    printf '{"dataset": "%s", "image": {"width": 48, "height": 48}, "compositor": {"name": "difference", "steps": [4, 5]}}\n' \
        "$DATASET" >"$SCRATCH/neighbours.json"
    run_tstyles -- render "$SCRATCH/neighbours.json" -o "$SCRATCH/difference-4-5.png"
    expect_exit 0
    expect_image "$SCRATCH/difference-4-5.png" 48 48
}

case_glsl_syntax_error() {
    custom_scene 'float best = 0.0;\nint winner = -1\nreturn float(winner);'
    # The compiler sees the missing ";" when it meets line 3.
    render_fails compositor.glsl "line 3: does not compile: syntax error"
}

case_glsl_type_error() {
    custom_scene 'float best = 0.0;\n\nreturn vec2(best);'
    render_fails compositor.glsl "line 3: does not compile:"
}

case_glsl_file_error() {
    printf 'int peak = -1;\nreturn peak + ;\n' >"$SCRATCH/peak.glsl"
    compositor_scene '{"file": "peak.glsl", "reads": "index-tstf"}'
    run_tstyles -- render "$SCENE" -o "$OUTPUT"
    expect_exit 2
    # Code in a file of its own: the message names that file.
    expect_error_line "$SCRATCH/peak.glsl" "line 2" "does not compile"
    expect_no_output "$OUTPUT"
}

case_sandbox_texture() {
    custom_scene 'float d = 0.0;\nd = texture(densities, vec3(0.5)).r;\nreturn d;'
    render_fails compositor.glsl 'line 2: "texture" is not available'
}

case_sandbox_time_steps() {
    custom_scene 'return timeSteps.steps[0].time.x;'
    render_fails compositor.glsl 'line 1: "timeSteps" is not available'
}

case_sandbox_while() {
    custom_scene 'int i = 0;\nwhile (i < count) { i++; }\nreturn float(i);'
    render_fails compositor.glsl 'line 2: "while" is not allowed'
}

case_sandbox_unbounded_loop() {
    custom_scene 'float s = 0.0;\nfor (int i = 0; i < 1000000; ++i) s += 1.0;\nreturn s;'
    render_fails compositor.glsl 'line 2: a loop must read'
}

case_sandbox_loop_variable() {
    custom_scene 'for (int i = 0; i < count; ++i) {\n  if (density[i] > 0.5) i -= 1;\n}\nreturn 0.0;'
    render_fails compositor.glsl 'line 2: the loop variable "i" may change only in its loop'"'"'s header'
}

case_sandbox_define() {
    custom_scene 'int peak = 0;\n#define count 1000000\nreturn float(peak);'
    render_fails compositor.glsl 'line 2: preprocessor directives are not allowed'
}

case_threshold_on_temporal_mip() {
    compositor_scene '{"name": "temporal-mip", "threshold": 0.5}'
    render_fails compositor.threshold "temporal-mip takes no threshold"
}

case_difference_steps_beyond_the_series() {
    local steps
    steps=$(dataset_step_count "$DATASET")
    compositor_scene "{\"name\": \"difference\", \"steps\": [0, $steps]}"
    render_fails "compositor.steps[1]" "is $steps (the series has $steps time-steps"
}

case_scene_writes_the_compositor_object() {
    run_tstyles -- scene "$DATASET" --tc first-arrival -o "$SCENE"
    expect_exit 0
    grep -qF '"name": "first-arrival"' "$SCENE" || fail "the scene has no compositor object: $(cat "$SCENE")"
    grep -qF '"threshold": 0.5' "$SCENE" || fail "the scene does not keep the threshold: $(cat "$SCENE")"
    # What `scene` wrote, `render` reads.
    run_tstyles -- render "$SCENE" --width 48 --height 48 -o "$OUTPUT"
    expect_exit 0
    expect_stdout_contains "first-arrival"
    expect_image "$OUTPUT" 48 48
}

case_automatic_scene_signed_colours() {
    # The automatic scene with a signed compositor: a diverging gradient TSTF, opaque at both ends.
    run_tstyles -- scene "$DATASET" --tc linear-trend -o "$SCENE"
    expect_exit 0
    expect_stdout_contains 'compositor linear-trend (--tc)'
    expect_stdout_contains '"blue-red"'
    local gradient
    gradient=$(tr -d ' \n' <"$SCENE" | grep -o '"gradient":{[^}]*}[^}]*}')
    echo "$gradient" | grep -qF '"opacity":[{"at":0.0,"opacity":1.0},{"at":0.5,"opacity":0.15}' ||
        fail "the gradient TSTF is not opaque at both ends and faint in the middle: $gradient"
    # A scene file keeps its own gradient TSTF whatever --tc says: its green-orange one, not the
    # blue-red one the automatic scene gives a signed compositor (97/255 apart at 32x32, measured).
    run_tstyles -- scene "$DATASET" -o "$SCRATCH/mip.json"
    expect_exit 0
    run_tstyles -- render "$SCRATCH/mip.json" --tc linear-trend --width 32 --height 32 -o "$SCRATCH/kept.png"
    expect_exit 0
    expect_image "$SCRATCH/kept.png" 32 32
    run_tstyles -- render "$DATASET" --tc linear-trend --width 32 --height 32 -o "$SCRATCH/automatic.png"
    expect_exit 0
    run_tstyles -- compare "$SCRATCH/kept.png" "$SCRATCH/automatic.png" --max-difference 20
    expect_exit 1
}

case_example_time_of_peak() {
    local example="$SOURCE_DIR/examples/compositors/time-of-peak.json"
    run_tstyles -- render "$example" --width 96 --height 96 -o "$SCRATCH/custom.png"
    expect_exit 0
    expect_stdout_contains "custom"
    expect_image "$SCRATCH/custom.png" 96 96
    run_tstyles -- render "$FIGURE4" --tc time-of-max --width 96 --height 96 -o "$SCRATCH/builtin.png"
    expect_exit 0
    # The same scene (camera, STF, index TSTF) as Figure 4: the same image as the built-in, exactly.
    run_tstyles -- compare "$SCRATCH/builtin.png" "$SCRATCH/custom.png" --max-difference 0 --max-mean 0
    expect_exit 0
}

run_case
