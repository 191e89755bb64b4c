#!/usr/bin/env bash
# End-to-end: `tstyles probe` on series whose value at every place and time is a known linear
# function (tests/cli/write_probe_samples.py), on each grid kind: the values at nodes and between
# them are the function's within the float32 density's rounding; a line gives the time x distance
# table; places outside every grid and malformed options end in exit code 2 naming the option.
# Usage: probe_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh); PYTHON is a
# Python with numpy.
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

PYTHON=${PYTHON:-python3}
WRITER="$SOURCE_DIR/tests/cli/write_probe_samples.py"

samples() {
    S="$SCRATCH/samples"
    "$PYTHON" "$WRITER" write "$S" || fail "write_probe_samples.py failed"
}

# probe_equals_function GRID X Y Z: `probe --at X,Y,Z --json` of the GRID series gives f there.
probe_equals_function() {
    local grid=$1 x=$2 y=$3 z=$4
    run_tstyles -- probe "$S/$grid/series.json" --at "$x,$y,$z" --json
    expect_exit 0
    "$PYTHON" "$WRITER" check "$OUT_FILE" "$x" "$y" "$z" || fail "$grid at ($x, $y, $z): values differ from f"
}

# exit 2 and one line "tstyles: OPTION: PROBLEM..." on stderr.
expect_option_error() {
    expect_exit 2
    [ "$(wc -l <"$ERR_FILE")" -eq 1 ] || fail "expected exactly one line on stderr: $(cat "$ERR_FILE")"
    case "$(cat "$ERR_FILE")" in
        "tstyles: $1: $2"*) ;;
        *) fail "stderr is not 'tstyles: $1: $2...': $(cat "$ERR_FILE")" ;;
    esac
}

# The world position `probe --voxel I,J,K --json` reports for a node.
node_position() {
    run_tstyles -- probe "$S/$1/series.json" --voxel "$2" --json
    expect_exit 0
    "$PYTHON" -c 'import json, sys; print(*json.load(open(sys.argv[1]))["at"])' "$OUT_FILE"
}

case_closed_form_every_grid() {
    samples
    # Nodes (the corners too) and places between them.
    probe_equals_function even 1 2 3
    probe_equals_function even 5 8 4
    probe_equals_function even 2.5 3.3 3.7
    probe_equals_function uneven 2.25 4.1 4.2
    probe_equals_function uneven 3 6 3.2
    probe_equals_function structured 2.75 5 3.8
    probe_equals_function structured 3.6 4.5 3.35
    # The rotated grid at a node and halfway between two nodes that differ in every index.
    local a b middle
    read -r -a a <<<"$(node_position rotated 2,1,1)"
    read -r -a b <<<"$(node_position rotated 3,2,2)"
    probe_equals_function rotated "${a[0]}" "${a[1]}" "${a[2]}"
    read -r -a middle <<<"$("$PYTHON" -c 'import sys; v = [float(t) for t in sys.argv[1:]]; print(*[(p + q) / 2 for p, q in zip(v[:3], v[3:])])' "${a[@]}" "${b[@]}")"
    probe_equals_function rotated "${middle[0]}" "${middle[1]}" "${middle[2]}"
    # The beam fan at a sample and halfway along its beam to the next range sample.
    local node between
    read -r -a node <<<"$("$PYTHON" -c 'import json, sys; print(*json.load(open(sys.argv[1]))["node_2_1_3"])' "$S/beam_nodes.json")"
    read -r -a between <<<"$("$PYTHON" -c 'import json, sys; print(*json.load(open(sys.argv[1]))["between_2_1_3_and_4"])' "$S/beam_nodes.json")"
    probe_equals_function beam "${node[0]}" "${node[1]}" "${node[2]}"
    probe_equals_function beam "${between[0]}" "${between[1]}" "${between[2]}"
}

# --voxel names a node of the first time-step's grid: the even grid's node (2, 1, 1) is at
# (1, 2, 3) + (2, 2, 0.5); the text table lists each time with its value.
case_voxel_and_table() {
    samples
    run_tstyles -- probe "$S/even/series.json" --voxel 2,1,1 --json
    expect_exit 0
    "$PYTHON" "$WRITER" check "$OUT_FILE" 3 4 3.5 || fail "--voxel 2,1,1 is not the node at (3, 4, 3.5)"
    run_tstyles -- probe "$S/even/series.json" --voxel 2,1,1
    expect_exit 0
    expect_stdout_contains "at (3, 4, 3.5) (no unit):"
    # f(3, 4, 3.5, 2.5) = 2 + 1.5 - 1 + 10.5 + 25
    expect_stdout_contains "  2  2.5  38"
    run_tstyles -- probe "$S/even/series.json" --voxel 2,1,1 --csv
    expect_exit 0
    expect_stdout_contains "time,label,value"
    expect_stdout_contains '2.5,"2.5",38'
}

# A line from (1, 4, 3.5) to (5, 4, 3.5) in 5 points: one row per time-step, one column per point,
# each f at that point.
case_along_a_line() {
    samples
    run_tstyles -- probe "$S/even/series.json" --along 1,4,3.5:5,4,3.5 --points 5 --csv
    expect_exit 0
    expect_stdout_contains "time,label,0,1,2,3,4"
    # f(x, 4, 3.5, 0) = 2 + 0.5 x - 1 + 10.5 = 11.5 + 0.5 x: 12, 12.5, 13, 13.5, 14.
    expect_stdout_contains '0,"0",12,12.5,13,13.5,14'
    expect_stdout_contains '1,"1",22,22.5,23,23.5,24'
    run_tstyles -- probe "$S/even/series.json" --along 1,4,3.5:5,4,3.5 --points 3 --json
    expect_exit 0
    grep -q '"distances": \[' "$OUT_FILE" || fail "--json of a line has no distances"
    # -o draws the table: a Hovmoeller diagram of the line, a line plot of a place (their pixels are
    # checked in tests/annotate/probe_plot_test.cpp).
    run_tstyles -- probe "$S/even/series.json" --along 1,4,3.5:5,4,3.5 --points 20 -o "$SCRATCH/line.png" --size 640x360
    expect_exit 0
    expect_image "$SCRATCH/line.png" 640 360
    run_tstyles -- probe "$S/even/series.json" --at 2,4,3.5 -o "$SCRATCH/place.png"
    expect_exit 0
    expect_image "$SCRATCH/place.png" 800 450
    run_tstyles -- probe "$S/even/series.json" --at 2,4,3.5 -o "$SCRATCH/no-such-folder/place.png"
    expect_exit 2
    expect_stderr_contains "does not exist"
    expect_no_output "$SCRATCH/no-such-folder/place.png"
}

case_bad_places_and_options() {
    samples
    run_tstyles -- probe "$S/even/series.json" --at 10,2,3
    expect_option_error "--at" "the place (10, 2, 3) is outside every time-step's grid; the series spans (1, 2, 3) to (5, 8, 4)"
    run_tstyles -- probe "$S/even/series.json" --at 1,2
    expect_option_error "--at" "expected a place X,Y,Z as three numbers separated by commas, got \"1,2\" (2 numbers)"
    run_tstyles -- probe "$S/even/series.json" --at 1,2,x
    expect_option_error "--at" "expected a place X,Y,Z as three numbers separated by commas, got \"1,2,x\""
    run_tstyles -- probe "$S/even/series.json" --voxel 5,0,0
    expect_option_error "--voxel" "node (5, 0, 0) is outside the first time-step's grid of 5 x 4 x 3 nodes"
    run_tstyles -- probe "$S/even/series.json" --along 1,2,3:1,2,3
    expect_option_error "--along" "the line (1, 2, 3) to (1, 2, 3) has zero length"
    run_tstyles -- probe "$S/even/series.json" --at 1,2,3 --voxel 0,0,0
    expect_option_error "--at" "give exactly one of --at X,Y,Z, --voxel I,J,K and --along A:B"
}

# A CF forecast written by netCDF4-python (tests/cli/write_probe_forecast.py): pressure levels
# that count down (stored 500 hPa first) are given in hPa as the file has them, and `--at` a node
# gives exactly the float32 values netCDF4 reads there (a masked one as null), with the file's times,
# time units and calendar; `info` lists the file's coordinates; a level beyond the file's is refused
# with the bounds in the file's coordinates.
case_netcdf4_forecast() {
    local forecast="$SCRATCH/forecast.nc"
    "$PYTHON" "$SOURCE_DIR/tests/cli/write_probe_forecast.py" write "$forecast" || fail "write_probe_forecast.py failed"
    run_tstyles -- info "$forecast"
    expect_exit 0
    expect_stdout_contains "File coordinates: (-100, 35, 500) to (-93, 40, 1000)"
    expect_stdout_contains "z = level (hPa, up, negated)"
    local place
    for place in "-98,36,700" "-93,40,500" "-100,35,1000" "-95,38,700"; do
        run_tstyles -- probe "$forecast" --at "$place" --json
        expect_exit 0
        "$PYTHON" "$SOURCE_DIR/tests/cli/write_probe_forecast.py" check "$forecast" "$OUT_FILE" ${place//,/ } ||
            fail "--at $place differs from netCDF4"
    done
    # Under the high ground at 1000 hPa every time-step is missing: an answer, not an error.
    run_tstyles -- probe "$forecast" --at -100,35,1000 --csv
    expect_exit 0
    expect_stdout_contains '0,"+0 h",'
    run_tstyles -- probe "$forecast" --at -98,36,-700
    expect_option_error "--at" "the place (-98, 36, -700) is outside every time-step's grid; the series spans (-100, 35, 500) to (-93, 40, 1000) (in the file's coordinates, as \`tstyles info\` lists them)"
}

run_case
