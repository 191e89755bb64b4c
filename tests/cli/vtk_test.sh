#!/usr/bin/env bash
# End-to-end: VTK XML files (.vti, .vts, .pvd, .series) written by VTK's own writers through `info`,
# `convert`, `render` and `view`: the values come back exactly in every encoding, the frame and the
# times are the files', and bad files end in exit code 2 with one line and nothing written.
# Usage: vtk_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh); VTK_PYTHON is a
# Python with python3-vtk9 and numpy.
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

SAMPLES_WRITER="$SOURCE_DIR/tests/cli/write_vtk_samples.py"
VTK_PYTHON=${VTK_PYTHON:-python3}

samples() {
    S="$SCRATCH/samples"
    "$VTK_PYTHON" "$SAMPLES_WRITER" write "$S" >/dev/null 2>"$SCRATCH/writer.txt" ||
        fail "write_vtk_samples.py failed: $(cat "$SCRATCH/writer.txt")"
}

# convert FILE [OPTIONS...] into $SCRATCH/out-NAME, then compare time-step STEP's raw values with
# the known ones: converted_values_equal NAME ARRAY STEP [ORDER] -- FILE [OPTIONS...]
converted_values_equal() {
    local name=$1 array=$2 step=$3 order=${4:-as-written}
    shift 4
    [ "$1" = "--" ] && shift
    run_tstyles -- convert "$@" -o "$SCRATCH/out-$name"
    expect_exit 0
    local raw
    raw=$(printf '%s/out-%s/t%02d.raw' "$SCRATCH" "$name" "$step")
    "$VTK_PYTHON" "$SAMPLES_WRITER" check "$raw" "$array" "$step" "$order" || fail "$name: values differ"
}

# render FILE -o OUT and expect exit 2, one line naming FILE and FIELD with PROBLEM, no image.
expect_refused() {
    local file=$1 field=$2 problem=$3
    shift 3
    run_tstyles -- render "$file" "$@" -o "$SCRATCH/refused.png" --backend osmesa --width 32 --height 32
    expect_exit 2
    expect_error_line "$file" "$field" "$problem"
    expect_no_output "$SCRATCH/refused.png"
}

case_values_every_encoding() {
    samples
    for variant in ascii binary binary_uint64 binary_zlib binary_zlib_blocks binary_lz4 binary_lzma appended_raw \
        appended_raw_zlib appended_raw_lz4 appended_base64 appended_base64_lzma big_endian big_endian_appended_zlib; do
        converted_values_equal "$variant" temperature 0 -- "$S/$variant.vti"
    done
    run_tstyles -- info "$S/appended_base64_lzma.vti"
    expect_exit 0
    expect_stdout_contains "Format: VTK XML ImageData"
    expect_stdout_contains "appended (base64), compressed by vtkLZMADataCompressor, UInt64 headers, little-endian"
    run_tstyles -- info "$S/big_endian_appended_zlib.vti"
    expect_exit 0
    expect_stdout_contains "appended (raw), compressed by vtkZLibDataCompressor, UInt64 headers, big-endian"
}

case_array_choice() {
    samples
    run_tstyles -- info "$S/binary.vti"
    expect_exit 0
    expect_stdout_contains "point array 'temperature' (Float32, the active Scalars array); the others, for --var: pressure, label, velocity (3 components)"
    converted_values_equal pressure pressure 0 -- "$S/binary_zlib.vti" --var pressure
    converted_values_equal label label 0 -- "$S/appended_raw_lz4.vti" --var label
    converted_values_equal velocity velocity-magnitude 0 -- "$S/binary_lzma.vti" --var velocity
    run_tstyles -- info "$S/binary.vti" --var velocity
    expect_stdout_contains "'velocity' has 3 components: its magnitude is shown"
    # No active Scalars: the first array of one component, pressure here.
    run_tstyles -- info "$S/no_active.vti"
    expect_exit 0
    expect_stdout_contains "point array 'pressure' (Int16, the first array of one component)"
    converted_values_equal no_active pressure 0 -- "$S/no_active.vti"
}

case_unknown_variable() {
    samples
    expect_refused "$S/binary.vti" "--var" "no point array named 'nope'; the point arrays are: pressure, label, velocity (3 components), temperature" --var nope
    expect_refused "$S/vector_only.vti" "PointData" "no point array of one component to show; name one with --var (a vector is read as its magnitude): velocity (3 components)"
}

case_pvd_and_series() {
    samples
    for list in plume.pvd plume.vti.series; do
        run_tstyles -- info "$S/$list"
        expect_exit 0
        expect_stdout_contains "Time-steps: 3"
        expect_stdout_contains "3 ImageData file(s) listed in $list, times as it gives them (no unit)"
        expect_stdout_contains "compressed by vtkZLibDataCompressor"
        for step in 0 1 2; do
            converted_values_equal "$list-$step" temperature "$step" -- "$S/$list"
        done
        # The times as listed; each step's origin moves 0.25 along x.
        tr -d ' \n' <"$SCRATCH/out-$list-0/series.json" >"$SCRATCH/manifest.txt"
        for expected in '"time":0.5' '"time":1.5' '"time":4.0' '"origin":[0.25,1.0,2.0]' \
            '"origin":[0.5,1.0,2.0]' '"spacing":[0.5,1.0,2.0]'; do
            grep -qF -- "$expected" "$SCRATCH/manifest.txt" || fail "$list: the manifest has no $expected"
        done
    done
    # Two parts at each time, listed out of time order: part 0 read, sorted by time, both said.
    sed -e 's|\(.*\)part="0" file="\(.*\)"/>|\1part="1" file="\2"/>\n\1part="0" file="\2"/>|' "$S/plume.pvd" |
        sed -e 's/timestep="0.5"/timestep="9"/' >"$S/parts.pvd"
    run_tstyles -- info "$S/parts.pvd"
    expect_exit 0
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "the collection has 2 parts at each time: only part 0 is read"
    expect_stdout_contains "the list is not in time order: its data sets are read sorted by time"
    # A list of files: one time-step each, times 0, 1, 2 in the order given.
    run_tstyles -- info "$S/plume/plume_2.vti" "$S/plume/plume_0.vti"
    expect_exit 0
    expect_stdout_contains "Time-steps: 2"
    expect_stdout_contains "one time-step each, times 0, 1, 2, ... in the order given"
    run_tstyles -- convert "$S/plume/plume_2.vti" "$S/plume/plume_0.vti" -o "$SCRATCH/list"
    expect_exit 0
    "$VTK_PYTHON" "$SAMPLES_WRITER" check "$SCRATCH/list/t00.raw" temperature 2 || fail "list: step 0 is not plume_2"
    "$VTK_PYTHON" "$SAMPLES_WRITER" check "$SCRATCH/list/t01.raw" temperature 0 || fail "list: step 1 is not plume_0"
}

case_frame() {
    samples
    # Direction: 90 degrees about z; Origin (1, 2, 3).
    converted_values_equal rotated temperature 0 -- "$S/rotated.vti"
    tr -d ' \n' <"$SCRATCH/out-rotated/series.json" >"$SCRATCH/rotated.txt"
    grep -qF '"origin":[1.0,2.0,3.0],"rotation":{"axis":[0.0,0.0,1.0],"angle_deg":90.0}' "$SCRATCH/rotated.txt" ||
        fail "rotated.vti: placement is not origin (1,2,3), 90 degrees about z: $(cat "$SCRATCH/rotated.txt")"
    # A reflection: x reversed, the first sample now the last (1 - 4 * 0.5 = -1 along x).
    converted_values_equal mirrored temperature 0 mirror-x -- "$S/mirrored.vti"
    tr -d ' \n' <"$SCRATCH/out-mirrored/series.json" >"$SCRATCH/mirrored.txt"
    grep -qF '"origin":[-1.0,2.0,3.0]' "$SCRATCH/mirrored.txt" || fail "mirrored.vti: origin is not (-1,2,3)"
    # An extent from (2, 0, 1): the first point at Origin + (2 * 0.5, 0, 1 * 2).
    converted_values_equal offset temperature 0 -- "$S/offset_extent.vti"
    tr -d ' \n' <"$SCRATCH/out-offset/series.json" >"$SCRATCH/offset.txt"
    grep -qF '"origin":[2.0,2.0,5.0]' "$SCRATCH/offset.txt" || fail "offset_extent.vti: origin is not (2,2,5)"
}

case_structured_grid() {
    samples
    run_tstyles -- info "$S/grid.vts"
    expect_exit 0
    expect_stdout_contains "Format: VTK XML StructuredGrid"
    expect_stdout_contains "structured 5x4x3"
    run_tstyles -- render "$S/grid.vts" -o "$SCRATCH/grid.png" --backend osmesa --width 64 --height 64
    expect_exit 0
    expect_image "$SCRATCH/grid.png" 64 64
}

# A RectilinearGrid (.vtr, VTK's writer): x and y even, z uneven (0, 1, 3), values as written.
case_rectilinear_grid() {
    samples
    run_tstyles -- info "$S/depth.vtr"
    expect_exit 0
    expect_stdout_contains "Format: VTK XML RectilinearGrid"
    expect_stdout_contains "rectilinear 5x4x3"
    expect_stdout_contains "World bounds: (10, -2, 0) to (12, 1, 3)"
    run_tstyles -- convert "$S/depth.vtr" -o "$SCRATCH/depth"
    expect_exit 0
    "$VTK_PYTHON" "$SAMPLES_WRITER" check "$SCRATCH/depth/t00.raw" temperature 0 || fail "depth.vtr's temperature differs"
    grep -q '"z": \[0.0, 1.0, 3.0\]' "$SCRATCH/depth/series.json" || fail "the uneven z levels were not kept: $(cat "$SCRATCH/depth/series.json")"
    run_tstyles -- render "$S/depth.vtr" -o "$SCRATCH/depth.png" --backend osmesa --width 64 --height 64
    expect_exit 0
    expect_image "$SCRATCH/depth.png" 64 64
    # z coordinates that do not increase: refused, naming the field.
    sed -e 's/^\( *\)0 1 3$/\10 3 1/' "$S/depth_ascii.vtr" >"$S/decreasing.vtr"
    grep -q "0 3 1" "$S/decreasing.vtr" || fail "the test could not rewrite the z coordinates"
    expect_refused "$S/decreasing.vtr" "Coordinates" "the z coordinates must increase strictly: 1 follows 3"
}

case_pieces() {
    samples
    run_tstyles -- info "$S/pieces.vti"
    expect_exit 0
    expect_stdout_contains "holds 3 pieces, assembled into its WholeExtent"
    run_tstyles -- convert "$S/pieces.vti" -o "$SCRATCH/pieces"
    expect_exit 0
    run_tstyles -- convert "$S/whole.vti" -o "$SCRATCH/whole"
    expect_exit 0
    cmp -s "$SCRATCH/pieces/t00.raw" "$SCRATCH/whole/t00.raw" || fail "pieces.vti and whole.vti read differently"
}

# The plume series as a hand-written tstyles manifest (raw float32 files by numpy) renders to the
# same pixels as its .pvd.
case_same_image_as_manifest() {
    samples
    mkdir -p "$SCRATCH/manifest"
    PYTHONPATH="$SOURCE_DIR/tests/cli" "$VTK_PYTHON" - "$SCRATCH/manifest" <<'PY' || fail "could not write the manifest"
import json, sys
from write_vtk_samples import known
folder = sys.argv[1]
steps = []
for step, time in enumerate([0.5, 1.5, 4.0]):
    known("temperature", step).tofile(f"{folder}/t{step:02d}.raw")
    steps.append({"time": time, "grid": {"type": "rectilinear", "dims": [5, 4, 3], "spacing": [0.5, 1, 2]},
                  "placement": {"origin": [0.25 * step, 1, 2]},
                  "values": {"file": f"t{step:02d}.raw", "type": "float32"}})
axes = [{"name": name} for name in "xyz"]
json.dump({"format": "tstyles-series", "version": 1, "name": "plume (temperature)", "axes": axes,
           "time_steps": steps}, open(f"{folder}/series.json", "w"))
PY
    run_tstyles -- render "$S/plume.pvd" -o "$SCRATCH/pvd.png" --backend osmesa --width 96 --height 96
    expect_exit 0
    expect_image "$SCRATCH/pvd.png" 96 96
    run_tstyles -- render "$SCRATCH/manifest" -o "$SCRATCH/manifest.png" --backend osmesa --width 96 --height 96
    expect_exit 0
    "$OIIOTOOL" "$SCRATCH/pvd.png" "$SCRATCH/manifest.png" --diff >"$SCRATCH/diff.txt" 2>&1 ||
        fail "the .pvd and the manifest render differently: $(cat "$SCRATCH/diff.txt")"
}

case_view_pvd() {
    have_xvfb || return 0
    samples
    view_and_screenshot "$S/plume.pvd" --size 400x300
}

case_missing_step_file() {
    samples
    rm "$S/plume/plume_1.vti"
    expect_refused "$S/plume.pvd" "DataSet (line 5)" "the file '$S/plume/plume_1.vti' does not exist"
    expect_refused "$S/plume.vti.series" "files[1]" "does not exist"
}

case_truncated_data() {
    samples
    head -c 2000 "$S/binary.vti" >"$S/cut.vti"
    expect_refused "$S/cut.vti" "" "bad XML at byte"
    # Appended raw data cut short: the XML is whole, the data is not.
    head -c 1500 "$S/appended_raw.vti" >"$S/cut_appended.vti"
    expect_refused "$S/cut_appended.vti" "DataArray 'temperature' (line 8)" "is truncated: its offset 1644 lies beyond"
    # A compressed block cut: its compressed size no longer fits the data.
    head -c 1900 "$S/appended_raw_zlib.vti" >"$S/cut_zlib.vti"
    expect_refused "$S/cut_zlib.vti" "DataArray 'temperature' (line 8)" "is truncated: its blocks need 162 compressed bytes"
}

case_header_disagrees_with_extent() {
    samples
    sed -e 's/Extent="0 4 0 3 0 2"/Extent="0 4 0 3 0 1"/g' "$S/binary.vti" >"$S/smaller.vti"
    expect_refused "$S/smaller.vti" "DataArray 'temperature' (line 23)" "its header gives 240 bytes of data, the extent and type need 160"
    sed -e 's/Extent="0 4 0 3 0 2"/Extent="0 4 0 3 0 3"/g' "$S/binary_zlib.vti" >"$S/larger.vti"
    expect_refused "$S/larger.vti" "DataArray 'temperature' (line 23)" "disagrees with the 320 bytes the extent and type need"
    sed -e 's/Extent="0 4 0 3 0 2"/Extent="0 4 0 3 0 3"/g' "$S/ascii.vti" >"$S/larger_ascii.vti"
    expect_refused "$S/larger_ascii.vti" "DataArray 'temperature' (line 70)" "is truncated: 60 of 80 numbers"
}

case_unknown_compressor_and_type() {
    samples
    sed -e 's/vtkZLibDataCompressor/vtkZstdDataCompressor/' "$S/binary_zlib.vti" >"$S/zstd.vti"
    expect_refused "$S/zstd.vti" "compressor" "unknown compressor 'vtkZstdDataCompressor'"
    sed -e 's/type="Float32" Name="temperature"/type="Float16" Name="temperature"/' "$S/binary.vti" >"$S/half.vti"
    expect_refused "$S/half.vti" "DataArray 'temperature' (line 23)" "unknown type 'Float16'"
}

case_not_a_volume() {
    samples
    sed -e 's/Extent="0 4 0 3 0 2"/Extent="0 4 0 3 0 0"/g' "$S/binary.vti" >"$S/flat.vti"
    expect_refused "$S/flat.vti" "WholeExtent" "a volume needs at least 2 samples along x, y and z, found 5 x 4 x 1"
}

case_bad_lists() {
    samples
    printf '{"file-series-version": "1.0", "files": [], "extra": 1}' >"$S/extra.series"
    expect_refused "$S/extra.series" "extra" "unknown key"
    printf '{"file-series-version": "1.0", "files": [{"name": "plume/plume_0.vti"}]}' >"$S/notime.series"
    expect_refused "$S/notime.series" "files[0].time" "missing; this key is required"
    printf '{"file-series-version": "1.0", "files": [{"name": "plume/plume_0.vti", "time": "0"}]}' >"$S/texttime.series"
    expect_refused "$S/texttime.series" "files[0].time" "expected a number, got a string"
    sed -e 's/timestep="1.5"/timestep="0.5"/' "$S/plume.pvd" >"$S/twice.pvd"
    expect_refused "$S/twice.pvd" "DataSet (line 5)" "is also the time of DataSet (line 4)"
    printf '<VTKFile type="Collection"><Collection><DataSet timestep="0" file="a.vti"/>' >"$S/open.pvd"
    expect_refused "$S/open.pvd" "" "bad XML at byte"
    run_tstyles -- info "$S/plume.pvd" "$S/plume.pvd"
    expect_exit 2
    expect_error_line "$S/plume.pvd" "" "a .pvd or .series file is a whole series: give it alone"
}

# VTK's parallel writers: a .pvti, .pvtr and .pvts, each listing a file per piece. The image reads
# the values whole.vti holds, the rectilinear grid the known temperature and its uneven z levels,
# the structured grid (the same analytic source on points) the values of whole.vti again.
case_parallel_files() {
    samples
    local P="$S/parallel"
    run_tstyles -- info "$P/pieces.pvti"
    expect_exit 0
    expect_stdout_contains "Format: VTK XML ImageData"
    expect_stdout_contains "pieces.pvti is parallel: 3 pieces in 3 files, assembled into its WholeExtent"
    run_tstyles -- convert "$P/pieces.pvti" -o "$SCRATCH/pvti"
    expect_exit 0
    run_tstyles -- convert "$S/whole.vti" -o "$SCRATCH/whole"
    expect_exit 0
    cmp -s "$SCRATCH/pvti/t00.raw" "$SCRATCH/whole/t00.raw" || fail "pieces.pvti and whole.vti read differently"
    run_tstyles -- info "$P/depth.pvtr"
    expect_exit 0
    expect_stdout_contains "depth.pvtr is parallel: 2 pieces in 2 files"
    expect_stdout_contains "World bounds: (10, -2, 0) to (12, 1, 3)"
    run_tstyles -- convert "$P/depth.pvtr" -o "$SCRATCH/pvtr"
    expect_exit 0
    "$VTK_PYTHON" "$SAMPLES_WRITER" check "$SCRATCH/pvtr/t00.raw" temperature 0 || fail "depth.pvtr's temperature differs"
    grep -q '"z": \[0.0, 1.0, 3.0\]' "$SCRATCH/pvtr/series.json" || fail "depth.pvtr's uneven z levels were not kept"
    run_tstyles -- info "$P/pieces.pvts"
    expect_exit 0
    expect_stdout_contains "Format: VTK XML StructuredGrid"
    expect_stdout_contains "structured 10x8x6"
    run_tstyles -- convert "$P/pieces.pvts" -o "$SCRATCH/pvts"
    expect_exit 0
    cmp -s "$SCRATCH/pvts/t00.raw" "$SCRATCH/whole/t00.raw" || fail "pieces.pvts and whole.vti read different values"
    run_tstyles -- render "$P/pieces.pvti" -o "$SCRATCH/pvti.png" --backend osmesa --width 64 --height 64
    expect_exit 0
    expect_image "$SCRATCH/pvti.png" 64 64
}

# A parallel file whose piece file is missing, or of another frame: refused, naming the piece.
case_parallel_refusals() {
    samples
    local P="$S/parallel"
    local line
    line=$(grep -n 'Source="pieces_1.vti"' "$P/pieces.pvti" | cut -d: -f1)
    mv "$P/pieces_1.vti" "$P/moved.vti"
    expect_refused "$P/pieces.pvti" "Piece (line $line)" "Source 'pieces_1.vti': the file '$P/pieces_1.vti' does not exist"
    # The piece file is what is wrong: the message names it.
    sed -e 's/Origin="0 0 0"/Origin="0.5 0 0"/' "$P/moved.vti" >"$P/pieces_1.vti"
    run_tstyles -- info "$P/pieces.pvti"
    expect_exit 2
    expect_error_line "$P/pieces_1.vti" "Origin" "differs from the Origin of pieces.pvti: the pieces of one image share its frame"
    sed -e 's/ImageData/RectilinearGrid/g' "$P/moved.vti" >"$P/pieces_1.vti"
    run_tstyles -- info "$P/pieces.pvti"
    expect_exit 2
    expect_error_line "$P/pieces_1.vti" "type" "a piece of pieces.pvti must be ImageData data, not RectilinearGrid"
}

# Legacy .vtk files written by VTK's legacy writers: the known arrays come back exactly from ASCII
# and BINARY files of versions 5.1 and 4.2, the FIELD arrays by --var, the rectilinear grid's uneven
# levels and the structured grid's points are kept.
case_legacy_files() {
    samples
    for variant in legacy_ascii legacy_binary legacy_binary_42; do
        converted_values_equal "$variant" temperature 0 -- "$S/$variant.vtk"
        converted_values_equal "$variant-pressure" pressure 0 -- "$S/$variant.vtk" --var pressure
        converted_values_equal "$variant-velocity" velocity-magnitude 0 -- "$S/$variant.vtk" --var velocity
    done
    run_tstyles -- info "$S/legacy_binary.vtk"
    expect_exit 0
    expect_stdout_contains "Format: VTK legacy STRUCTURED_POINTS"
    expect_stdout_contains "point array 'temperature' (Float32, the active Scalars array); the others, for --var: pressure, label, velocity (3 components)"
    expect_stdout_contains "data of legacy_binary.vtk: BINARY (big-endian)"
    run_tstyles -- info "$S/legacy_depth.vtk"
    expect_exit 0
    expect_stdout_contains "Format: VTK legacy RECTILINEAR_GRID"
    expect_stdout_contains "World bounds: (10, -2, 0) to (12, 1, 3)"
    run_tstyles -- convert "$S/legacy_depth.vtk" -o "$SCRATCH/legacy_depth"
    expect_exit 0
    "$VTK_PYTHON" "$SAMPLES_WRITER" check "$SCRATCH/legacy_depth/t00.raw" temperature 0 || fail "legacy_depth.vtk's temperature differs"
    grep -q '"z": \[0.0, 1.0, 3.0\]' "$SCRATCH/legacy_depth/series.json" || fail "legacy_depth.vtk's uneven z levels were not kept"
    run_tstyles -- info "$S/legacy_grid.vtk"
    expect_exit 0
    expect_stdout_contains "Format: VTK legacy STRUCTURED_GRID"
    expect_stdout_contains "structured 5x4x3"
    # The same data as legacy and as XML: the same picture.
    run_tstyles -- render "$S/legacy_grid.vtk" -o "$SCRATCH/legacy_grid.png" --backend osmesa --width 64 --height 64
    expect_exit 0
    run_tstyles -- render "$S/grid.vts" -o "$SCRATCH/grid.png" --backend osmesa --width 64 --height 64
    expect_exit 0
    cmp -s "$SCRATCH/legacy_grid.png" "$SCRATCH/grid.png" || fail "legacy_grid.vtk and grid.vts render differently"
}

# A series of numbered legacy files, listed in a .pvd or given as a list: one time-step each.
case_legacy_series() {
    samples
    run_tstyles -- info "$S/legacy.pvd"
    expect_exit 0
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "3 STRUCTURED_POINTS file(s) listed in legacy.pvd"
    converted_values_equal legacy-pvd temperature 2 -- "$S/legacy.pvd"
    run_tstyles -- info "$S"/legacy_series/flow_*.vtk
    expect_exit 0
    expect_stdout_contains "one time-step each, times 0, 1, 2, ... in the order given"
    converted_values_equal legacy-list temperature 1 -- "$S"/legacy_series/flow_*.vtk
    # Numbered files out of number order: read as given, and said.
    run_tstyles -- info "$S/legacy_series/flow_0002.vtk" "$S/legacy_series/flow_0000.vtk"
    expect_exit 0
    expect_stdout_contains "the files are numbered (flow_#.vtk) but not given in number order: flow_0000.vtk comes after flow_0002.vtk; the time-steps follow the order given"
}

# Damaged and unsupported legacy files: one line naming the file and the keyword, exit 2.
case_legacy_refusals() {
    samples
    head -c 300 "$S/legacy_binary.vtk" >"$S/legacy_cut.vtk"
    expect_refused "$S/legacy_cut.vtk" "SCALARS temperature" "is truncated"
    sed -e 's/^DATASET STRUCTURED_POINTS/DATASET POLYDATA/' "$S/legacy_ascii.vtk" >"$S/legacy_poly.vtk"
    expect_refused "$S/legacy_poly.vtk" "DATASET" "'POLYDATA' is not read: only STRUCTURED_POINTS, STRUCTURED_GRID and RECTILINEAR_GRID"
    sed -e '/^Z_COORDINATES/{n;s/^0 1 3 *$/0 3 1/}' "$S/legacy_depth.vtk" >"$S/legacy_decreasing.vtk"
    grep -q "^0 3 1" "$S/legacy_decreasing.vtk" || fail "the test could not rewrite the z coordinates"
    expect_refused "$S/legacy_decreasing.vtk" "Z_COORDINATES" "the z coordinates must increase strictly: 1 follows 3"
    expect_refused "$S/legacy_ascii.vtk" "--var" "no point array named 'nope'; the point arrays are: temperature, pressure, label, velocity (3 components)" --var nope
}

run_case
