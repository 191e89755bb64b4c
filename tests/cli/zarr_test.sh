#!/usr/bin/env bash
# End-to-end: OME-Zarr stores (written at test time by tests/data/ome_zarr_stores.py with zarr-python
# and by hand) through `tstyles info`, `convert`, `render` and `view`; damaged stores and impossible
# metadata end in exit code 2, one line naming the file, the field and the problem, nothing written.
# Usage: zarr_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh); PYTHON: an
# interpreter with zarr and numpy (ctest passes the one CMake found).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

PYTHON=${PYTHON:-python3}
STORES="$SOURCE_DIR/tests/data/ome_zarr_stores.py"

# store KIND: writes $SCRATCH/KIND.zarr and sets Z to it.
store() {
    Z="$SCRATCH/$1.zarr"
    "$PYTHON" "$STORES" "$1" "$Z" || fail "ome_zarr_stores.py $1 failed"
}

# edit_json FILE PYTHON_STATEMENT: runs the statement on the file's JSON as `d` and writes it back.
edit_json() {
    "$PYTHON" -c "import json, sys
d = json.load(open(sys.argv[1]))
$2
json.dump(d, open(sys.argv[1], 'w'))" "$1" || fail "could not edit $1"
}

# render_refused FIELD PROBLEM [FILE]: `render` of the store fails with that line and writes nothing.
render_refused() {
    run_tstyles -- render "$Z" -o "$SCRATCH/out.png" --width 64 --height 64
    expect_exit 2
    expect_error_line "${3:-$Z}" "$1" "$2"
    expect_no_output "$SCRATCH/out.png"
}

case_info_v2() {
    store v2_blosc_zstd
    run_tstyles -- info "$Z"
    expect_exit 0
    expect_stdout_contains "Format: OME-Zarr 0.4"
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "Read: OME-Zarr 0.4 on Zarr v2, axes t, c, z, y, x, image \"cells\""
    expect_stdout_contains "Read: level 0 of 2, the finest (--level picks another)"
    expect_stdout_contains "Read: channel 0 (\"nuclei\") of 2 (--channel picks another)"
    expect_stdout_contains "Read: array 0: <u2, codecs blosc"
    expect_stdout_contains "Read: turned 180 degrees about x"
}

# Every store holds the same values: converted, their raw files are the same bytes, and those are
# the values written (as float32, x fastest), chunk by chunk, the missing one as its fill value.
case_convert_matches_written() {
    local kind first=""
    for kind in v2_blosc_lz4 v2_big_endian v2_nested v2_fortran v3_blosc v3_sharded; do
        store "$kind"
        run_tstyles -- convert "$Z" -o "$SCRATCH/$kind" --channel 1
        expect_exit 0
        if [ -z "$first" ]; then
            first=$kind
            "$PYTHON" -c "import sys, numpy as np
sys.path.insert(0, sys.argv[1])
import ome_zarr_stores as s
values = s.known_values()
for t in range(3):
    read = np.fromfile(f'{sys.argv[2]}/t{t:02d}.raw', dtype='<f4')
    assert np.array_equal(read, values[t, 1].astype('<f4').ravel()), t" "$SOURCE_DIR/tests/data" "$SCRATCH/$kind" \
                || fail "$kind: the converted values are not those written"
        else
            for raw in "$SCRATCH/$first"/t*.raw; do
                cmp -s "$raw" "$SCRATCH/$kind/$(basename "$raw")" || fail "$kind differs from $first in $(basename "$raw")"
            done
        fi
    done
}

# The store and its conversion to a manifest render to the same picture (the manifest keeps the
# placement, times and axes): the reader's frame is all the automatic scene sees.
case_render_matches_manifest() {
    store v3_gzip
    run_tstyles -- convert "$Z" -o "$SCRATCH/manifest"
    expect_exit 0
    run_tstyles -- render "$Z" -o "$SCRATCH/store.png" --width 96 --height 96 --backend osmesa
    expect_exit 0
    expect_image "$SCRATCH/store.png" 96 96
    run_tstyles -- render "$SCRATCH/manifest" -o "$SCRATCH/manifest.png" --width 96 --height 96 --backend osmesa
    expect_exit 0
    "$OIIOTOOL" "$SCRATCH/store.png" "$SCRATCH/manifest.png" --diff >"$SCRATCH/diff.txt" 2>&1 \
        || fail "the store and its manifest render differently: $(cat "$SCRATCH/diff.txt")"
}

case_view_store() {
    have_xvfb || return 0
    store v2_gzip
    view_and_screenshot "$Z" --size 400x300
}

case_truncated_chunk() {
    store v2_zlib
    truncate -s 40 "$Z/0/1.0.0.0.0"
    render_refused "zlib" "cut short" "$Z/0/1.0.0.0.0"
}

case_truncated_blosc_chunk() {
    store v2_blosc_lz4
    truncate -s 30 "$Z/0/2.0.1.1.1"
    render_refused "blosc" "not a whole blosc buffer" "$Z/0/2.0.1.1.1"
}

case_chunk_of_another_size() {
    store v2_none
    head -c 100 /dev/zero >"$Z/0/1.0.0.0.0"
    render_refused "" "decodes to 100 bytes where the chunk holds 96" "$Z/0/1.0.0.0.0"
}

case_damaged_shard_index() {
    store v3_sharded
    printf 'XXXX' | dd of="$Z/0/c/1/0/0/0/0" bs=1 seek=$(($(stat -c %s "$Z/0/c/1/0/0/0/0") - 20)) conv=notrunc 2>/dev/null
    render_refused "crc32c" "checksum does not match" "$Z/0/c/1/0/0/0/0"
}

case_unknown_compressor() {
    store v2_zlib
    edit_json "$Z/0/.zarray" 'd["compressor"] = {"id": "bz2", "level": 1}'
    render_refused "compressor.id" '"bz2" is not a compressor this reader knows' "$Z/0/.zarray"
}

case_unknown_codec() {
    store v3_gzip
    edit_json "$Z/0/zarr.json" 'd["codecs"][1] = {"name": "bz2"}'
    render_refused "codecs[1]" '"bz2" is not a codec this reader knows' "$Z/0/zarr.json"
}

case_transpose_refused() {
    store v3_gzip
    edit_json "$Z/0/zarr.json" 'd["codecs"].insert(0, {"name": "transpose", "configuration": {"order": [4, 3, 2, 1, 0]}})'
    render_refused "codecs[0]" "a transpose that reorders the axes is not supported" "$Z/0/zarr.json"
}

case_filters_refused() {
    store v2_zlib
    edit_json "$Z/0/.zarray" 'd["filters"] = [{"id": "delta", "dtype": "<u2"}]'
    render_refused "filters" "are not supported" "$Z/0/.zarray"
}

case_unsupported_dtypes() {
    local dtype
    for dtype in '<i8' '<c8' '<U4' '<u4'; do
        store v2_none
        edit_json "$Z/0/.zarray" "d['dtype'] = '$dtype'"
        render_refused "dtype" "\"$dtype\" is not a data type this reader stores" "$Z/0/.zarray"
    done
    store v3_gzip
    edit_json "$Z/0/zarr.json" 'd["data_type"] = "uint64"'
    render_refused "data_type" '"uint64" is not a data type this reader stores' "$Z/0/zarr.json"
}

case_chunks_do_not_match_shape() {
    store v2_gzip
    edit_json "$Z/0/.zarray" 'd["chunks"] = [1, 3, 4, 4]'
    render_refused "chunks" "has 4 dimensions, the shape 5" "$Z/0/.zarray"
}

case_missing_level() {
    store v2_gzip
    rm "$Z/1/.zarray"
    run_tstyles -- render "$Z" --level 1 -o "$SCRATCH/out.png" --width 64 --height 64
    expect_exit 2
    expect_error_line "$Z/1/.zarray" "" "is missing"
    expect_no_output "$SCRATCH/out.png"
}

case_image_without_z() {
    store v2_gzip
    # A 2D time-lapse: t, c, y, x, with transforms of four values.
    edit_json "$Z/.zattrs" 'm = d["multiscales"][0]
del m["axes"][2]
for level in m["datasets"]:
    for transform in level["coordinateTransformations"]:
        del transform[transform["type"]][2]'
    render_refused "multiscales[0].axes" "(t, c, y, x) is an axis order that cannot be a volume over time" "$Z/.zattrs"
}

# Zarr and OME metadata are read through JsonField, in the wording of every JSON the program reads.
case_metadata_of_the_wrong_type() {
    store v2_gzip
    edit_json "$Z/0/.zarray" 'd["shape"] = "5x4"'
    render_refused "shape" "expected an array, got a string" "$Z/0/.zarray"
    store v3_blosc
    edit_json "$Z/0/zarr.json" 'd["chunk_grid"]["configuration"]["chunk_shape"][1] = 0'
    render_refused "chunk_grid.configuration.chunk_shape[1]" "expected a whole number from 1 to 2^53, got 0" "$Z/0/zarr.json"
    edit_json "$Z/0/zarr.json" 'del d["node_type"]'
    render_refused "node_type" "missing; this key is required" "$Z/0/zarr.json"
}

case_bad_json() {
    store v2_gzip
    head -c 50 "$Z/.zattrs" >"$Z/cut" && mv "$Z/cut" "$Z/.zattrs"
    render_refused "" "not valid JSON" "$Z/.zattrs"
}

case_zero_scale() {
    store v3_blosc
    edit_json "$Z/zarr.json" 'd["attributes"]["ome"]["multiscales"][0]["datasets"][0]["coordinateTransformations"][0]["scale"][3] = 0'
    render_refused "multiscales[0].datasets[0].coordinateTransformations" 'the scale of axis "y" is 0' "$Z/zarr.json"
}

case_channel_out_of_range() {
    store v2_lz4
    run_tstyles -- render "$Z" --channel 2 -o "$SCRATCH/out.png" --width 64 --height 64
    expect_exit 2
    expect_error_line "$Z" "--channel" "is 2; the image has 2 channels (0 to 1)"
    expect_no_output "$SCRATCH/out.png"
}

case_level_out_of_range() {
    store v2_lz4
    run_tstyles -- info "$Z" --level 2
    expect_exit 2
    expect_error_line "$Z" "--level" "is 2; the image has 2 levels (0 to 1)"
}

case_option_for_another_format() {
    store v2_lz4
    run_tstyles -- info "$Z" --var temp
    expect_exit 2
    expect_error_line "$Z" "--var" "does not apply to OME-Zarr files"
}

run_case
