#!/usr/bin/env bash
# End-to-end (issue 43): a path the user wrote that the system refuses (a name or path too long, a
# file used as a folder, a loop of links, a NUL, a FIFO or folder where a file goes) ends in exit 2,
# one line naming the file and the field, and nothing written, through every command that takes paths.
#
# CI runs the tests as root, for whom permission bits stop nothing: a chmod-made EACCES cannot be
# seen here. It goes through the same function as the cases below (throwUserPathError in
# src/core/user_paths.cpp, tested there for ENAMETOOLONG and ELOOP); ENOTDIR stands in for it.
# Usage: paths_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

# 300 characters: over NAME_MAX (255) on every Linux file system.
LONG=$(printf 'a%.0s' $(seq 300))
# 17 names of 250 characters: each allowed, together 4267 characters, over PATH_MAX (4096).
DEEP=$SCRATCH
for _ in $(seq 17); do DEEP="$DEEP/$(printf 'd%.0s' $(seq 250))"; done

# What is in the scratch folder, but for what tstyles prints: to see that a refusal wrote nothing.
scratch_listing() {
    find "$SCRATCH" -mindepth 1 ! -name stdout.txt ! -name stderr.txt | sort
}

# One row of a table: runs tstyles with ARGS (bounded: a FIFO must not block), and expects exit 2,
# one line "FILE: FIELD: ...PROBLEM..." and the scratch folder as it was.
# refused FILE FIELD PROBLEM -- ARGS...
refused() {
    local file=$1 field=$2 problem=$3
    shift 4
    local before
    before=$(scratch_listing)
    RC=0
    echo "+ tstyles $*" | cut -c1-200 >&2
    timeout 20 "$TSTYLES" "$@" >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
    [ "$RC" != 124 ] || fail "tstyles $* did not finish within 20 s"
    expect_exit 2
    expect_error_line "$file" "$field" "$problem"
    [ "$(scratch_listing)" = "$before" ] || fail "the refused command wrote: $(diff <(echo "$before") <(scratch_listing))"
}

# A one-case suite whose case names SCENE (relative to the suite): write_suite SCENE.
write_suite() {
    printf '{"cases": [{"scene": "%s"}]}\n' "$1" >"$SCRATCH/suite.json"
}

# A manifest of the bundled dataset's first time-step with its values file named FILE ("<NUL>" in
# it becomes a NUL character).
write_manifest_naming() {
    python3 - "$DATASET" "$SCRATCH/series.json" "$1" <<'PY'
import json, sys
source, target, name = sys.argv[1:]
manifest = json.load(open(source))
manifest["time_steps"] = manifest["time_steps"][:1]
manifest["time_steps"][0]["values"]["file"] = name.replace("<NUL>", "\0")
manifest["time_steps"][0].pop("mask", None)
json.dump(manifest, open(target, "w"))
PY
}

# The issue's reproducer, in the layout it was found in: data/scenes/ beside data/superellipsoid/.
case_reproducer_style_name() {
    mkdir -p "$SCRATCH/data/scenes"
    ln -s "$(dirname "$DATASET")" "$SCRATCH/data/superellipsoid"
    cp "$SOURCE_DIR/tests/cli/reproducers/scene_style_name_too_long.json" "$SCRATCH/data/scenes/"
    refused "$SCRATCH/data/scenes/scene_style_name_too_long.json" "tstf.index.color[2].style" \
        "the name is too long for the file system (5000 characters)" -- \
        render "$SCRATCH/data/scenes/scene_style_name_too_long.json" -o "$SCRATCH/out.png"
}

case_name_too_long() {
    local problem="the name is too long for the file system (30"
    refused "$SCRATCH/$LONG.json" "" "$problem" -- render "$SCRATCH/$LONG.json" -o "$SCRATCH/out.png"
    refused "$SCRATCH/$LONG.nc" "" "$problem" -- info "$SCRATCH/$LONG.nc"
    refused "$SCRATCH/$LONG.nc" "" "$problem" -- convert "$SCRATCH/$LONG.nc" -o "$SCRATCH/out"
    refused "$SCRATCH/$LONG.png" "-o" "$problem" -- render "$DATASET" -o "$SCRATCH/$LONG.png"
    refused "$SCRATCH/$LONG.mp4" "-o" "$problem" -- animate "$DATASET" --orbit 30 -o "$SCRATCH/$LONG.mp4"
    refused "$SCRATCH/$LONG/" "-o" "$problem" -- animate "$DATASET" --orbit 30 -o "$SCRATCH/$LONG/"
    refused "$SCRATCH/$LONG" "-o" "$problem" -- convert "$DATASET" -o "$SCRATCH/$LONG"
    refused "$SCRATCH/$LONG.json" "-o" "$problem" -- scene "$DATASET" -o "$SCRATCH/$LONG.json"
    refused "$SCRATCH/$LONG.json" "" "$problem" -- check "$SCRATCH/$LONG.json"
    refused "$SCRATCH/$LONG.png" "" "$problem" -- compare "$SCRATCH/$LONG.png" "$SCRATCH/$LONG.png"
    refused "$SCRATCH/$LONG.json" "" "$problem" -- compare "$SCRATCH/a.png" "$SCRATCH/a.png" \
        --thresholds "$SCRATCH/$LONG.json"
    write_suite "$LONG.json"
    refused "$SCRATCH/suite.json" "cases[0].scene" "$problem" -- check "$SCRATCH/suite.json"
    write_scene "$SCRATCH/dataset.json" "$LONG/series.json"
    refused "$SCRATCH/dataset.json" "dataset" "$problem" -- render "$SCRATCH/dataset.json" -o "$SCRATCH/out.png"
    write_scene "$SCRATCH/style.json" "$DATASET" "\"stf\": {\"color\": [{\"at\": 0, \"style\": \"$LONG.png\"}]}"
    refused "$SCRATCH/style.json" "stf.color[0].style" "$problem" -- render "$SCRATCH/style.json" -o "$SCRATCH/out.png"
    write_manifest_naming "$LONG.raw"
    refused "$SCRATCH/series.json" "time_steps[0].values.file" "$problem" -- info "$SCRATCH/series.json"
}

# The output checks come before any rendering: a bad -o costs nothing.
case_output_name_too_long_with_pictures() {
    write_scene "$SCRATCH/scene.json"
    run_tstyles -- render "$SCRATCH/scene.json" -o "$SCRATCH/a.png"
    expect_exit 0
    refused "$SCRATCH/$LONG.png" "--diff" "the name is too long" -- \
        compare "$SCRATCH/a.png" "$SCRATCH/a.png" --diff "$SCRATCH/$LONG.png"
    refused "$SCRATCH/$LONG.png" "--side-by-side" "the name is too long" -- \
        compare "$SCRATCH/a.png" "$SCRATCH/a.png" --side-by-side "$SCRATCH/$LONG.png"
    write_suite scene.json
    refused "$SCRATCH/$LONG" "--report" "the name is too long" -- check "$SCRATCH/suite.json" --report "$SCRATCH/$LONG"
}

case_path_too_long() {
    local problem="the path is too long for the file system ("
    refused "$DEEP/x.json" "" "$problem" -- render "$DEEP/x.json" -o "$SCRATCH/out.png"
    refused "$DEEP/x.nc" "" "$problem" -- info "$DEEP/x.nc"
    refused "$DEEP/out.png" "-o" "$problem" -- render "$DATASET" -o "$DEEP/out.png"
    refused "$DEEP/out.json" "-o" "$problem" -- scene "$DATASET" -o "$DEEP/out.json"
    write_scene "$SCRATCH/dataset.json" "$DEEP/series.json"
    refused "$SCRATCH/dataset.json" "dataset" "$problem" -- render "$SCRATCH/dataset.json" -o "$SCRATCH/out.png"
}

# A file where the path needs a folder (ENOTDIR), also what a closed folder looks like to root.
case_file_used_as_folder() {
    echo "not a folder" >"$SCRATCH/file.txt"
    local under="$SCRATCH/file.txt"
    local problem="a part of the path is a file, not a folder"
    refused "$under/x.json" "" "$problem" -- render "$under/x.json" -o "$SCRATCH/out.png"
    refused "$under/x.nc" "" "$problem" -- info "$under/x.nc"
    refused "$under/out.png" "-o" "$under is a file, not a folder" -- render "$DATASET" -o "$under/out.png"
    refused "$under/out.mp4" "-o" "$problem" -- animate "$DATASET" --orbit 30 -o "$under/out.mp4"
    refused "$under/frames" "-o" "$under is a file, not a folder" -- animate "$DATASET" --orbit 30 -o "$under/frames/"
    refused "$under/out" "-o" "$problem" -- convert "$DATASET" -o "$under/out"
    refused "$under/out.json" "-o" "$under is a file, not a folder" -- scene "$DATASET" -o "$under/out.json"
    refused "$under/suite.json" "" "$problem" -- check "$under/suite.json"
    refused "$under/a.png" "" "$problem" -- compare "$under/a.png" "$under/a.png"
    write_suite file.txt/scene.json
    refused "$SCRATCH/suite.json" "cases[0].scene" "$problem" -- check "$SCRATCH/suite.json"
    write_scene "$SCRATCH/scene.json"
    write_suite scene.json
    refused "$under/report" "--report" "$problem" -- check "$SCRATCH/suite.json" --report "$under/report"
    write_scene "$SCRATCH/dataset.json" "file.txt/series.json"
    refused "$SCRATCH/file.txt/series.json" "" "$problem" -- render "$SCRATCH/dataset.json" -o "$SCRATCH/out.png"
    write_manifest_naming "file.txt/t00.raw"
    refused "$SCRATCH/series.json" "time_steps[0].values.file" "$problem" -- info "$SCRATCH/series.json"
}

case_loop_of_links() {
    ln -s loop-b "$SCRATCH/loop-a"
    ln -s loop-a "$SCRATCH/loop-b"
    local loop="$SCRATCH/loop-a"
    local problem="a loop of symbolic links"
    refused "$loop" "" "$problem" -- render "$loop" -o "$SCRATCH/out.png"
    refused "$loop" "" "$problem" -- info "$loop"
    refused "$loop" "-o" "$problem" -- render "$DATASET" -o "$loop"
    refused "$loop" "-o" "$problem" -- render "$DATASET" -o "$loop/x.png"
    refused "$loop" "-o" "$problem" -- convert "$DATASET" -o "$loop"
    refused "$loop" "" "$problem" -- check "$loop"
    refused "$loop" "" "$problem" -- compare "$loop" "$loop"
    write_scene "$SCRATCH/dataset.json" "loop-a"
    refused "$loop" "" "$problem" -- render "$SCRATCH/dataset.json" -o "$SCRATCH/out.png"
    write_scene "$SCRATCH/style.json" "$DATASET" '"stf": {"color": [{"at": 0, "style": "./loop-a"}]}'
    refused "$loop" "style" "$problem" -- render "$SCRATCH/style.json" -o "$SCRATCH/out.png"
    write_manifest_naming "loop-a"
    refused "$SCRATCH/series.json" "time_steps[0].values.file" "$problem" -- info "$SCRATCH/series.json"
}

# JSON can spell a NUL (\u0000); the system call would end the name there and open another file.
case_nul_in_name() {
    local problem="the name holds a NUL character"
    write_scene "$SCRATCH/dataset.json" '../data\u0000/series.json'
    refused "$SCRATCH/dataset.json" "dataset" "$problem" -- render "$SCRATCH/dataset.json" -o "$SCRATCH/out.png"
    write_scene "$SCRATCH/style.json" "$DATASET" '"stf": {"color": [{"at": 0, "style": "bright\u0000.png"}]}'
    refused "$SCRATCH/style.json" "stf.color[0].style" "$problem" -- render "$SCRATCH/style.json" -o "$SCRATCH/out.png"
    write_suite 'scene\u0000.json'
    refused "$SCRATCH/suite.json" "cases[0].scene" "$problem" -- check "$SCRATCH/suite.json"
    write_manifest_naming "t00<NUL>.raw"
    refused "$SCRATCH/series.json" "time_steps[0].values.file" "$problem" -- info "$SCRATCH/series.json"
}

# A FIFO would block a reader for ever, and a writer's rename would replace it: both refused.
case_fifo() {
    mkfifo "$SCRATCH/fifo.json" "$SCRATCH/fifo.png" "$SCRATCH/fifo.mp4" "$SCRATCH/fifo.nc"
    local reading="is not a regular file"
    local writing="is not a regular file (a FIFO, device or socket), not replaced"
    refused "$SCRATCH/fifo.json" "" "$reading" -- render "$SCRATCH/fifo.json" -o "$SCRATCH/out.png"
    refused "$SCRATCH/fifo.nc" "" "$reading" -- info "$SCRATCH/fifo.nc"
    refused "$SCRATCH/fifo.png" "-o" "$writing" -- render "$DATASET" -o "$SCRATCH/fifo.png"
    refused "$SCRATCH/fifo.mp4" "-o" "$writing" -- animate "$DATASET" --orbit 30 -o "$SCRATCH/fifo.mp4"
    refused "$SCRATCH/fifo.json" "-o" "$writing" -- scene "$DATASET" -o "$SCRATCH/fifo.json"
    refused "$SCRATCH/fifo.nc" "-o" "is not a folder" -- convert "$DATASET" -o "$SCRATCH/fifo.nc"
    refused "$SCRATCH/fifo.json" "" "$reading" -- check "$SCRATCH/fifo.json"
    refused "$SCRATCH/fifo.png" "" "$reading" -- compare "$SCRATCH/fifo.png" "$SCRATCH/fifo.png"
    refused "$SCRATCH/fifo.json" "" "$reading" -- compare "$SCRATCH/fifo.png" "$SCRATCH/fifo.png" \
        --thresholds "$SCRATCH/fifo.json"
    write_scene "$SCRATCH/style.json" "$DATASET" '"stf": {"color": [{"at": 0, "style": "fifo.png"}]}'
    refused "$SCRATCH/fifo.png" "" "$reading" -- render "$SCRATCH/style.json" -o "$SCRATCH/out.png"
}

case_folder_for_file() {
    mkdir -p "$SCRATCH/folder.png" "$SCRATCH/folder.json"
    refused "$SCRATCH/folder.png" "-o" "is a folder, not an image file" -- render "$DATASET" -o "$SCRATCH/folder.png"
    refused "$SCRATCH/folder.json" "-o" "is a folder, not a scene file" -- scene "$DATASET" -o "$SCRATCH/folder.json"
    refused "$SCRATCH/folder.png" "" "is a folder" -- compare "$SCRATCH/folder.png" "$SCRATCH/folder.png"
    refused "$SCRATCH/folder.json" "" "is a folder, not a thresholds file" -- compare "$SCRATCH/folder.png" \
        "$SCRATCH/folder.png" --thresholds "$SCRATCH/folder.json"
    write_suite folder.json
    refused "$SCRATCH/suite.json" "cases[0].scene" "no such scene file" -- check "$SCRATCH/suite.json"
    echo "a file" >"$SCRATCH/report.txt"
    write_scene "$SCRATCH/scene.json"
    write_suite scene.json
    refused "$SCRATCH/report.txt" "--report" "is a file, not a report folder" -- \
        check "$SCRATCH/suite.json" --report "$SCRATCH/report.txt"
    write_scene "$SCRATCH/style.json" "$DATASET" '"stf": {"color": [{"at": 0, "style": "folder.png"}]}'
    refused "$SCRATCH/folder.png" "" "is a folder" -- render "$SCRATCH/style.json" -o "$SCRATCH/out.png"
}

run_case
