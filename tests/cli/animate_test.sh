#!/usr/bin/env bash
# End-to-end: `tstyles animate` writes movies and frame folders whose frames are the scenes that
# `render --frame K` draws; bad keyframes and Ctrl+C leave nothing behind.
# Usage: animate_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh); PROBE_VIDEO
# names the tests' movie prober.
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

FIGURE1="$SOURCE_DIR/data/scenes/figure1-focus-step3.json"
HURRICANE="$SOURCE_DIR/data/hurricane/series.json"

# Frame K of `animate ARGS` (written to a folder) equals `render --frame K ARGS`, bit for bit.
frame_matches_render() {
    local input=$1 frame=$2
    shift 2
    run_tstyles -- animate "$input" -o "$SCRATCH/frames/" --width 64 --height 64 "$@"
    expect_exit 0
    local name
    name=$(printf 'frame-%04d.png' "$frame")
    [ -f "$SCRATCH/frames/$name" ] || fail "no $name in the frames folder: $(ls "$SCRATCH/frames")"
    run_tstyles -- render "$input" -o "$SCRATCH/single.png" --width 64 --height 64 --frame "$frame" "$@"
    expect_exit 0
    "$OIIOTOOL" --fail 0 --diff "$SCRATCH/frames/$name" "$SCRATCH/single.png" >"$SCRATCH/diff.txt" ||
        fail "frame $frame of animate differs from render --frame $frame: $(cat "$SCRATCH/diff.txt")"
    # And the animation moves: the first and this frame differ.
    if "$OIIOTOOL" --fail 0 --diff "$SCRATCH/frames/frame-0000.png" "$SCRATCH/frames/$name" >/dev/null; then
        fail "frame $frame is the same picture as frame 0: nothing moved"
    fi
}

case_focus_sweep_frame() { frame_matches_render "$FIGURE1" 13 --sweep-focus 1 --frames 20; }
case_exposure_frame() { frame_matches_render "$HURRICANE" 5 --exposure grow --frames 8; }
case_orbit_frame() { frame_matches_render "$FIGURE1" 3 --orbit 90 --frames 6 --annotate; }
case_camera_path_frame() { frame_matches_render "$HURRICANE" 4 --elevation 40 --zoom 1.5 --frames 6; }

# Each movie format decodes back to the frames, size and rate asked for.
movie_decodes() {
    local extension=$1 fps=$2
    run_tstyles -- animate "$FIGURE1" -o "$SCRATCH/movie.$extension" --width 64 --height 48 --sweep-focus 1 \
        --smooth --frames 9 --fps "$fps"
    expect_exit 0
    expect_stdout_contains "wrote $SCRATCH/movie.$extension (9 frames,"
    local probed
    probed=$("$PROBE_VIDEO" "$SCRATCH/movie.$extension") || fail "the movie does not decode"
    case "$probed" in
        "9 64x48 $fps "*) ;;
        *) fail "expected 9 frames of 64x48 at $fps fps, decoded: $probed" ;;
    esac
    [ -z "$(find "$SCRATCH" -name '*.tmp*' -o -name '.*partial*')" ] || fail "temporary files left: $(ls -a "$SCRATCH")"
}

case_mp4() { movie_decodes mp4 24; }
case_webm() { movie_decodes webm 25; }
case_gif() { movie_decodes gif 10; }

case_scene_animation_section() {
    write_scene "$SCRATCH/scene.json" "$DATASET" '"animation": {"frames": 4, "fps": 8, "tracks": [
        {"value": "camera.orbit.azimuth_deg", "keys": [[0, 0], [4, 180]]}]}'
    run_tstyles -- animate "$SCRATCH/scene.json" -o "$SCRATCH/frames/"
    expect_exit 0
    expect_stdout_contains "(4 frames as PNG, 64x64 at 8 fps;"
    [ "$(find "$SCRATCH/frames" -name 'frame-*.png' | wc -l)" -eq 4 ] || fail "expected 4 frames"
}

# A bad key: exit 2, the file and key named, nothing written.
bad_animation() {
    local section=$1 expected=$2
    write_scene "$SCRATCH/scene.json" "$DATASET" "\"animation\": $section"
    run_tstyles -- animate "$SCRATCH/scene.json" -o "$SCRATCH/movie.mp4"
    expect_exit 2
    expect_stderr_contains "$SCRATCH/scene.json: $expected"
    [ ! -e "$SCRATCH/movie.mp4" ] || fail "movie.mp4 was written"
    [ "$(ls -A "$SCRATCH" | grep -vc -e stdout.txt -e stderr.txt -e scene.json)" -eq 0 ] || fail "files left: $(ls -A "$SCRATCH")"
}

case_unknown_key() {
    bad_animation '{"tracks": [{"value": "camera.orbit.azimuth_deg", "keys": [[0, 0]], "ease": 1}]}' \
        "animation.tracks[0].ease: unknown key"
}
case_keys_out_of_order() {
    bad_animation '{"tracks": [{"value": "camera.orbit.azimuth_deg", "keys": [[4, 0], [2, 9]]}]}' \
        "animation.tracks[0].keys[1][0]: frames must increase from key to key: 2 comes after 4"
}
case_missing_group() {
    bad_animation '{"tracks": [{"focus": "tstf.index", "group": 3, "keys": [[0, 0], [9, 5]]}]}' \
        "animation.tracks[0].group: the curve tstf.index has no node in group 3"
}
case_exposure_past_the_series() {
    bad_animation '{"tracks": [{"value": "exposure.last", "keys": [[0, 0], [9, 40]]}]}' \
        "animation: at frame"
}
case_no_animation() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- animate "$SCRATCH/scene.json" -o "$SCRATCH/movie.mp4"
    expect_exit 2
    expect_stderr_contains "animation: the scene has no animation section; add one (docs/animation.md) or give a preset"
}
case_unwritable_output() {
    run_tstyles -- animate "$FIGURE1" -o "$SCRATCH/no/such/folder/movie.mp4" --orbit 90
    expect_exit 2
    expect_stderr_contains "movie.mp4: -o: the folder $SCRATCH/no/such/folder does not exist"
    run_tstyles -- animate "$FIGURE1" -o "$SCRATCH/movie.avi" --orbit 90
    expect_exit 2
    expect_stderr_contains "movie.avi: -o: cannot write movies of this type; use .mp4, .webm or .gif"
    run_tstyles -- animate "$FIGURE1" -o "$SCRATCH/odd.mp4" --orbit 90 --width 63
    expect_exit 2
    expect_stderr_contains "odd.mp4: size: 63x512 has an odd side; MP4 movies (yuv420p) need an even width and height"
}

# Ctrl+C in the middle: exit 130, and neither the movie nor its temporary file is left.
case_interrupt_leaves_nothing() {
    echo "+ tstyles animate (interrupted once it renders)" >&2
    "$TSTYLES" animate "$HURRICANE" -o "$SCRATCH/movie.mp4" --orbit 360 --frames 2000 --width 128 --height 128 \
        >"$OUT_FILE" 2>"$ERR_FILE" &
    local pid=$!
    # A background job of a script starts with SIGINT ignored, so a signal sent before tstyles
    # catches it would be lost: wait for the first progress line (the handler is in place by then;
    # a slow start, as under the sanitizers, takes longer than any fixed wait).
    local waited=0
    until grep -q "rendering frame" "$ERR_FILE" 2>/dev/null; do
        sleep 0.2
        waited=$((waited + 1))
        [ "$waited" -lt 600 ] || { kill -9 "$pid"; fail "no progress line in 120 s"; }
    done
    kill -INT "$pid"
    RC=0
    wait "$pid" || RC=$?
    expect_exit 130
    expect_stderr_contains "interrupted; $SCRATCH/movie.mp4 was not written"
    [ -z "$(ls -A "$SCRATCH" | grep -v -e stdout.txt -e stderr.txt)" ] || fail "files left: $(ls -A "$SCRATCH")"
}

run_case
