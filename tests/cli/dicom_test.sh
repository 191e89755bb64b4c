#!/usr/bin/env bash
# End-to-end: DICOM series (folders, file lists, enhanced multi-frame files) written by pydicom
# (tests/data/dicom_samples.py) through `tstyles info`, `render`, `convert` and `view`; the values,
# geometry, times and series choice read back as written, and bad inputs end in exit code 2 with
# one line naming the file, the tag and the problem, nothing written.
# Usage: dicom_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

# The Python that has pydicom and numpy (ctest passes CMake's; by hand, the system's).
PYTHON=${PYTHON:-/usr/bin/python3}
WRITER="$SOURCE_DIR/tests/data/dicom_samples.py"

# samples NAME...: the named samples of dicom_samples.py under $S.
samples() {
    S="$SCRATCH/samples"
    "$PYTHON" "$WRITER" "$S" "$@" || fail "dicom_samples.py failed"
}

# One DICOM element rewritten in a copy of a file, by pydicom: rewrite FILE KEYWORD PYTHON_VALUE.
rewrite() {
    "$PYTHON" -c "
import sys, pydicom
ds = pydicom.dcmread(sys.argv[1])
setattr(ds, sys.argv[2], eval(sys.argv[3]))
ds.save_as(sys.argv[1])" "$1" "$2" "$3" || fail "could not rewrite $2 in $1"
}

# The mean of the R, G and B means (0 .. 255) of HEIGHT rows of an image from row TOP (oiiotool
# cuts them into a file of their own, then --stats): mean_brightness FILE TOP HEIGHT.
mean_brightness() {
    local file=$1 top=$2 height=$3 width cut="$SCRATCH/rows-$2.png"
    width=$("$OIIOTOOL" --info "$file" | sed -E 's/.*: +([0-9]+) x.*/\1/')
    "$OIIOTOOL" "$file" --cut "${width}x${height}+0+${top}" -o "$cut" || fail "oiiotool cannot cut $file"
    "$OIIOTOOL" --stats "$cut" | awk '/Stats Avg:/ {print ($3 + $4 + $5) / 3; exit}'
}

case_info_cine_folder() {
    samples cine
    run_tstyles -- info "$S/cine"
    expect_exit 0
    expect_stdout_contains "Format: DICOM"
    # Both series listed, by SeriesNumber; the larger taken.
    expect_stdout_contains 'Read: DICOM series 1: UID 1.2.826.0.1.3680043.10.1187.1, number 1, "scout", MR, 3 files (3 frames of 8 x 8)'
    expect_stdout_contains 'Read: DICOM series 2: UID 1.2.826.0.1.3680043.10.1187.5, number 5, "cine short axis", MR, 24 files (24 frames of 16 x 12) - taken (the largest'
    expect_stdout_contains "Read: 1 files without the DICM magic left out"
    expect_stdout_contains "Read: 6 slices 2.5 mm apart"
    expect_stdout_contains "Read: 4 time-steps ordered by TemporalPositionIdentifier, times from TriggerTime (ms)"
    expect_stdout_contains "Time-steps: 4"
    # t * 1000 + z * 200 + y * 16 + x over 4 x 6 x 12 x 16 values.
    expect_stdout_contains "Value range: [0, 4191]"
    expect_stdout_contains "Axes: x = x (mm, right), y = y (mm, anterior), z = z (mm, superior)"
    expect_stdout_contains "Time: milliseconds"
    expect_stdout_contains "rectilinear 16x12x6"
    expect_stdout_contains "(0.6, 0.8, 2.5)"
    expect_stdout_contains "120 ms"
}

case_series_choice() {
    samples cine
    run_tstyles -- info "$S/cine" --series 1
    expect_exit 0
    expect_stdout_contains "scout\", MR, 3 files (3 frames of 8 x 8) - taken (--series 1)"
    expect_stdout_contains "Time-steps: 1"
    expect_stdout_contains "rectilinear 8x8x3"
    expect_stdout_contains "Value range: [1, 3]"
    run_tstyles -- info "$S/cine" --series 1.2.826.0.1.3680043.10.1187.5
    expect_exit 0
    expect_stdout_contains "Time-steps: 4"
    run_tstyles -- info "$S/cine" --series 3
    expect_exit 2
    expect_error_line "$S/cine" "--series" "names no series here: give a number from 1 to 2, numbers separated by commas, all, or a SeriesInstanceUID: 1 (UID 1.2.826.0.1.3680043.10.1187.1); 2 (UID 1.2.826.0.1.3680043.10.1187.5)"
}

case_list_of_files() {
    samples cine
    # The cine's files named one by one, in shuffled order: the tags decide, not the order.
    mapfile -t files < <(find "$S/cine" -name 'IM*' | sort -r)
    run_tstyles -- info "${files[@]}"
    expect_exit 0
    expect_stdout_contains "Time-steps: 4"
    expect_stdout_contains "Value range: [0, 4191]"
    # A file that is not DICOM among them.
    printf 'plain text\n' >"$SCRATCH/notes.dcm"
    run_tstyles -- info "${files[@]}" "$SCRATCH/notes.dcm"
    expect_exit 2
    expect_error_line "$SCRATCH/notes.dcm" "" "is shorter than a DICOM preamble"
}

case_ct_uneven_slices() {
    samples ct
    run_tstyles -- info "$S/ct"
    expect_exit 0
    expect_stdout_contains "Read: 4 slices unevenly spaced (z positions kept as they are)"
    expect_stdout_contains "(0.5, 0.5, uneven)"
    # Stored x*7 + y*13 + z*100 - 50 (signed), minus 1024: -1074 .. 63 + 91 + 300 - 50 - 1024.
    expect_stdout_contains "Value range: [-1074, -620]"
    expect_stdout_contains "Read: one time-step"
}

case_enhanced_multiframe() {
    samples enhanced
    run_tstyles -- info "$S/enhanced.dcm"
    expect_exit 0
    expect_stdout_contains "Format: DICOM"
    expect_stdout_contains "1 file (12 frames of 8 x 6) - taken (the only one)"
    expect_stdout_contains "Read: 3 time-steps ordered by TemporalPositionIdentifier, times in seconds from the first acquisition"
    expect_stdout_contains "Time-steps: 3"
    # (t * 100 + z * 20 + y * 8 + x) * 0.5 + 10: 10 .. 10 + 0.5 * 307.
    expect_stdout_contains "Value range: [10, 163.5]"
    expect_stdout_contains "Time: seconds"
    expect_stdout_contains "rectilinear 8x6x4"
    expect_stdout_contains "(1, 1.5, 2)"
}

case_render_head_up() {
    samples head_up
    run_tstyles -- render "$S/head_up" -o "$SCRATCH/head.png" --backend osmesa
    expect_exit 0
    expect_image "$SCRATCH/head.png" 512 512
    # The head (the last, brightest slices) is at the top of the picture, the feet at the bottom.
    local top bottom
    top=$(mean_brightness "$SCRATCH/head.png" 96 96)
    bottom=$(mean_brightness "$SCRATCH/head.png" 320 96)
    # About 24 against 16 of 255 when this was written; a head-down picture has them the other way.
    awk -v top="$top" -v bottom="$bottom" 'BEGIN { exit !(top > bottom + 4) }' ||
        fail "the top rows (mean $top) are not brighter than the bottom rows (mean $bottom): the head is not up"
}

case_same_picture_as_nifti() {
    samples cine cine_nifti
    run_tstyles -- render "$S/cine" -o "$SCRATCH/dicom.png" --backend osmesa --width 128 --height 128
    expect_exit 0
    run_tstyles -- render "$S/cine.nii" -o "$SCRATCH/nifti.png" --backend osmesa --width 128 --height 128
    expect_exit 0
    # The NIfTI's sform is float32: positions differ from the DICOM's doubles in the 7th digit, so a
    # few edge pixels may differ by a step; everything else is the same picture.
    run_tstyles -- compare "$SCRATCH/nifti.png" "$SCRATCH/dicom.png" --max-difference 8 --max-failing-share 0.5 \
        --side-by-side "$SCRATCH/side_by_side.png"
    expect_exit 0
}

case_convert_keeps_values() {
    samples enhanced
    run_tstyles -- convert "$S/enhanced.dcm" -o "$SCRATCH/converted"
    expect_exit 0
    run_tstyles -- info "$SCRATCH/converted"
    expect_exit 0
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "Value range: [10, 163.5]"
    expect_stdout_contains "Axes: x = x (mm, right), y = y (mm, anterior), z = z (mm, superior)"
}

case_missing_slice() {
    samples cine
    # Time-step 2 (TemporalPositionIdentifier 3) of slice 3 removed.
    local gone
    gone=$("$PYTHON" -c "
import pathlib, sys, pydicom
for path in pathlib.Path(sys.argv[1]).rglob('IM*'):
    ds = pydicom.dcmread(path, stop_before_pixels=True)
    if ds.SOPInstanceUID.endswith('.5.2.3'):
        print(path)" "$S/cine")
    [ -n "$gone" ] || fail "no file of time-step 2, slice 3"
    rm "$gone"
    run_tstyles -- render "$S/cine" -o "$SCRATCH/out.png"
    expect_exit 2
    expect_error_line "$S/cine" "" "time-step 2 (TemporalPositionIdentifier 3) lacks the slice at position"
    expect_no_output "$SCRATCH/out.png"
}

case_truncated_file() {
    samples cine
    local file
    file=$(find "$S/cine" -name 'IM*' | sort | head -n 1)
    truncate -s -100 "$file"
    run_tstyles -- render "$S/cine" -o "$SCRATCH/out.png"
    expect_exit 2
    expect_error_line "$file" "(7FE0,0010) PixelData" "truncated"
    expect_no_output "$SCRATCH/out.png"
    # Cut inside the file meta information: every element header is walked before GDCM reads the file.
    truncate -s 200 "$file"
    run_tstyles -- info "$S/cine"
    expect_exit 2
    expect_error_line "$file" "" "is truncated or damaged at byte 192 of 200: a file meta element claims more bytes"
}

# Issue 54: a file whose RescaleSlope is 0, or missing beside a RescaleIntercept, is refused by name in
# the header walk, before GDCM (which asserts on it) decodes it; expect_error_line's one line on
# stderr shows that nothing the reader process' libraries print reaches the terminal.
case_zero_rescale_slope() {
    samples ct
    "$PYTHON" -c "
import sys, pydicom
ds = pydicom.dcmread(sys.argv[1])
ds.RescaleSlope = '0'
ds.save_as(sys.argv[1])" "$S/ct/ct2.dcm" || fail "could not rewrite ct2.dcm"
    run_tstyles -- info "$S/ct"
    expect_exit 2
    expect_error_line "$S/ct/ct2.dcm" "(0028,1053) RescaleSlope" "is 0: every pixel would read as the intercept"
    # The reproducer's shape: an intercept without its slope (GDCM asserts on it while decoding).
    "$PYTHON" -c "
import sys, pydicom
ds = pydicom.dcmread(sys.argv[1])
del ds.RescaleSlope
ds.save_as(sys.argv[1])" "$S/ct/ct2.dcm" || fail "could not rewrite ct2.dcm"
    run_tstyles -- info "$S/ct"
    expect_exit 2
    expect_error_line "$S/ct/ct2.dcm" "(0028,1053) RescaleSlope" "is missing, though RescaleIntercept"
}

case_different_size() {
    samples ct
    "$PYTHON" -c "
import sys, numpy as np, pydicom
ds = pydicom.dcmread(sys.argv[1])
ds.Rows = 4
ds.PixelData = np.zeros((4, 10), dtype='<i2').tobytes()
ds.save_as(sys.argv[1])" "$S/ct/ct2.dcm" || fail "could not rewrite ct2.dcm"
    run_tstyles -- info "$S/ct"
    expect_exit 2
    expect_error_line "$S/ct/ct2.dcm" "(0028,0010) Rows" "the image is 10 x 4"
}

case_different_orientation() {
    samples ct
    rewrite "$S/ct/ct1.dcm" ImageOrientationPatient '["1", "0", "0", "0", "0.8", "0.6"]'
    run_tstyles -- info "$S/ct"
    expect_exit 2
    expect_error_line "$S/ct/ct1.dcm" "(0020,0037) ImageOrientationPatient" "must share one orientation"
}

case_colour_refused() {
    samples ct
    "$PYTHON" -c "
import sys, pathlib, numpy as np, pydicom
for path in pathlib.Path(sys.argv[1]).glob('*.dcm'):
    ds = pydicom.dcmread(path)
    ds.SamplesPerPixel = 3
    ds.PhotometricInterpretation = 'RGB'
    ds.PlanarConfiguration = 0
    ds.BitsAllocated = ds.BitsStored = 8
    ds.HighBit = 7
    ds.PixelRepresentation = 0
    ds.PixelData = np.zeros((8, 10, 3), dtype=np.uint8).tobytes()
    ds.save_as(path)" "$S/ct" || fail "could not write RGB files"
    run_tstyles -- info "$S/ct"
    expect_exit 2
    expect_error_line "$S/ct/ct0.dcm" "(0028,0002) SamplesPerPixel" "colour (RGB, YBR) images are not read"
}

case_no_image_series() {
    mkdir -p "$SCRATCH/reports"
    "$PYTHON" -c "
import sys
sys.path.insert(0, sys.argv[2])
import dicom_samples as s
ds = s.new_file('1.2.840.10008.5.1.4.1.1.88.11', s.UID_ROOT + '31', s.UID_ROOT + '30', 9, 'report', 'SR')
s.save(ds, sys.argv[1] + '/report.dcm')" "$SCRATCH/reports" "$SOURCE_DIR/tests/data" || fail "could not write the report"
    run_tstyles -- info "$SCRATCH/reports"
    expect_exit 2
    expect_error_line "$SCRATCH/reports" "" "holds no DICOM image series (1 DICOM files, none with image pixels)"
}

case_single_slice() {
    samples ct
    run_tstyles -- render "$S/ct/ct0.dcm" -o "$SCRATCH/out.png"
    expect_exit 2
    expect_error_line "$S/ct/ct0.dcm" "(0020,0032) ImagePositionPatient" "a volume needs at least 2 slices"
    expect_no_output "$SCRATCH/out.png"
}

case_series_option_elsewhere() {
    run_tstyles -- info "$DATASET" --series 1
    expect_exit 2
    expect_error_line "$DATASET" "--series"
}

# A multi-phase CT, one series per phase (dicom_samples.py write_phases): by default the three
# phases are read as three time-steps in acquisition order (series 3, 5, 4: 0, 50 and 160 s); the
# lung-kernel copy of the arterial phase and the scout are not phases. HU = phase_value.
case_phases_default() {
    samples phases
    run_tstyles -- info "$S/phases"
    expect_exit 0
    expect_stdout_contains "series 3: UID 1.2.826.0.1.3680043.10.1187.15.3, number 3, \"arterial\", CT, 5 files (5 frames of 12 x 10) - taken (phases of one study: the same frame of reference, modality, grid and acquisition parameters, acquired at different times; --series 3 takes one)"
    expect_stdout_contains "series 5: UID 1.2.826.0.1.3680043.10.1187.15.5, number 5, \"portal venous\", CT, 5 files (5 frames of 12 x 10) - taken"
    if grep -q "arterial lung.* - taken" "$OUT_FILE"; then fail "the lung-kernel series was taken as a phase"; fi
    expect_stdout_contains "Read: series 3,5,4 read as 3 time-steps in acquisition order, times in seconds from the first acquisition"
    expect_stdout_contains "Series: arterial, portal venous, delayed"
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "rectilinear 12x10x5"
    expect_stdout_contains "Time: seconds"
    grep -qE '^ +1 +50 s ' "$OUT_FILE" || fail "time-step 1 (portal venous) is not at 50 s"
    grep -qE '^ +2 +160 s ' "$OUT_FILE" || fail "time-step 2 (delayed) is not at 160 s"
    run_tstyles -- convert "$S/phases" -o "$SCRATCH/converted"
    expect_exit 0
    "$PYTHON" -c "
import sys, numpy as np
for phase in range(3):
    values = np.fromfile(f'{sys.argv[1]}/t{phase:02d}.raw', '<f4').reshape(5, 10, 12)
    z, y, x = np.indices(values.shape)
    expected = 40 + 30 * phase + z * 5 + y * 2 + x - 12  # in the files' order (a half turn, no mirror)
    assert np.array_equal(values, expected), (phase, np.abs(values - expected).max())
" "$SCRATCH/converted" || fail "the converted phases differ from phase_value"
}

# Chosen by hand: any series on one grid stack (2,3: the lung kernel with the arterial phase), a
# series on another grid is refused by name, a number given twice is refused, one number is one series.
case_phases_chosen() {
    samples phases
    run_tstyles -- info "$S/phases" --series 2,3
    expect_exit 0
    expect_stdout_contains "Time-steps: 2"
    run_tstyles -- info "$S/phases" --series 4
    expect_exit 0
    expect_stdout_contains "Time-steps: 1"
    expect_stdout_contains "delayed"
    run_tstyles -- info "$S/phases" --series all
    expect_exit 2
    expect_error_line "$S/phases" "--series" "series 2 is 12 x 10 x 5 voxels, not 8 x 8 x 3 of series 1: series read as the time-steps of one must share one grid"
    run_tstyles -- info "$S/phases" --series 3,3
    expect_exit 2
    expect_error_line "$S/phases" "--series" "\"3,3\" names series 3 twice"
    run_tstyles -- info "$S/phases" --series 3,9
    expect_exit 2
    expect_error_line "$S/phases" "--series" "\"3,9\" has \"9\", no series here"
}

# RT Dose as a planning system exports it: one multi-frame file, no functional groups, the frames
# placed along the slice normal by GridFrameOffsetVector and scaled to gray by DoseGridScaling
# (dicom_samples.py: dose = (z * 100 + y * 10 + x) / 1000 Gy, 3 mm between frames). Offsets from
# the first frame and offsets as z coordinates read the same volume.
case_rt_dose_frame_offsets() {
    samples rtdose rtdose_absolute
    run_tstyles -- info "$S/rtdose/dose.dcm"
    expect_exit 0
    expect_stdout_contains "Read: frames placed by GridFrameOffsetVector (3004,000C), offsets from the first frame"
    expect_stdout_contains "DoseGridScaling applied"
    expect_stdout_contains "Time-steps: 1"
    expect_stdout_contains "Value range: [0, 0.479]"
    expect_stdout_contains "rectilinear 10x8x5"
    expect_stdout_contains "(2, 2.5, 3)"
    grep -v "^File:\|GridFrameOffsetVector" "$OUT_FILE" >"$SCRATCH/relative.txt"
    run_tstyles -- info "$S/rtdose_absolute/dose.dcm"
    expect_exit 0
    expect_stdout_contains "Read: frames placed by GridFrameOffsetVector (3004,000C), z coordinates"
    grep -v "^File:\|GridFrameOffsetVector" "$OUT_FILE" >"$SCRATCH/absolute.txt"
    diff "$SCRATCH/relative.txt" "$SCRATCH/absolute.txt" >&2 || fail "absolute offsets read another volume"
    # The values as written, in the file's order: LPS into RAS is a half turn about z, not a mirror,
    # so the turn is in the placement and the values keep their order.
    run_tstyles -- convert "$S/rtdose/dose.dcm" -o "$SCRATCH/converted"
    expect_exit 0
    "$PYTHON" -c "
import sys, numpy as np
values = np.fromfile(sys.argv[1], '<f4').reshape(5, 8, 10)
z, y, x = np.indices(values.shape)
expected = (z * 100 + y * 10 + x) / 1000.0
assert np.allclose(values, expected, rtol=0, atol=1e-6), np.abs(values - expected).max()
" "$SCRATCH/converted/t00.raw" || fail "the converted dose differs from (z * 100 + y * 10 + x) / 1000"
}

# Offsets that are neither from the first frame (0 first) nor the z coordinates of an axial grid.
case_rt_dose_offsets_refused() {
    samples rtdose_oblique_absolute
    run_tstyles -- info "$S/rtdose_oblique/dose.dcm"
    expect_exit 2
    expect_error_line "$S/rtdose_oblique/dose.dcm" "(3004,000C) GridFrameOffsetVector" "starts at 40"
}

# A CD export (DCMTK's dcmmkdir over the cine and the CT), every name then lower-cased as a Linux
# mount of an ISO 9660 disc shows them: $CD holds it.
cd_export() {
    command -v dcmmkdir >/dev/null || fail "dcmmkdir missing (dcmtk; tools/install_dependencies.sh installs it)"
    samples cine ct
    CD="$SCRATCH/cd"
    mkdir -p "$CD/CT"
    cp -r "$S/cine/." "$CD/"
    rm "$CD/README"
    mv "$CD/sub" "$CD/SUB"
    local file name
    for file in "$S"/ct/ct*.dcm; do
        name=$(basename "$file" .dcm)
        cp "$file" "$CD/CT/${name^^}"
    done
    (cd "$CD" && dcmmkdir --recurse +I +id . >"$SCRATCH/dcmmkdir.log" 2>&1) ||
        fail "dcmmkdir failed: $(tail -3 "$SCRATCH/dcmmkdir.log")"
    find "$CD" -depth -mindepth 1 | while read -r file; do
        mv "$file" "$(dirname "$file")/$(basename "$file" | tr '[:upper:]' '[:lower:]')" 2>/dev/null || true
    done
    [ -f "$CD/dicomdir" ] || fail "no dicomdir after lower-casing"
}

# Choosing the DICOMDIR reads the series it indexes, as choosing the folder does.
case_dicomdir_cd_export() {
    cd_export
    run_tstyles -- info "$CD"
    expect_exit 0
    grep -v "^File:" "$OUT_FILE" >"$SCRATCH/folder.txt"
    run_tstyles -- info "$CD/dicomdir"
    expect_exit 0
    expect_stdout_contains "Read: DICOMDIR: 31 files referenced by its 36 directory records"
    expect_stdout_contains "Time-steps: 4"
    grep -v "^File:\|^Read: DICOMDIR" "$OUT_FILE" >"$SCRATCH/dicomdir.txt"
    diff "$SCRATCH/folder.txt" "$SCRATCH/dicomdir.txt" >&2 || fail "the DICOMDIR reads otherwise than its folder"
    run_tstyles -- info "$CD/dicomdir" --series 2
    expect_exit 0
    expect_stdout_contains "\"chest\", CT, 4 files (4 frames of 10 x 8) - taken (--series 2)"
    expect_stdout_contains "Time-steps: 1"
    expect_stdout_contains "rectilinear 10x8x4"
}

# A DICOMDIR copied without one of its files: the record that names it, exit 2.
case_dicomdir_file_missing() {
    cd_export
    rm "$CD/ct/ct2"
    run_tstyles -- info "$CD/dicomdir"
    expect_exit 2
    expect_error_line "$CD/dicomdir" "" "(0004,1500) ReferencedFileID: \"CT\\CT2\" names $CD/ct/CT2, which is not there"
    # A record that climbs out of the disc's folder is refused before anything is opened there.
    "$PYTHON" -W ignore -c "
import sys, pydicom
ds = pydicom.dcmread(sys.argv[1])
next(r for r in ds.DirectoryRecordSequence if 'ReferencedFileID' in r).ReferencedFileID = ['..', 'etc', 'passwd']
ds.save_as(sys.argv[1])" "$CD/dicomdir" || fail "could not rewrite the DICOMDIR"
    run_tstyles -- info "$CD/dicomdir"
    expect_exit 2
    expect_error_line "$CD/dicomdir" "" "\"..\\etc\\passwd\" is not a path inside the DICOMDIR's folder"
}

case_view_folder() {
    have_xvfb || return 0
    samples cine
    view_and_screenshot "$S/cine" --size 640x480
    grep -q "cine" "$SCRATCH/saved.json" || fail "the saved scene does not name the cine folder"
}

run_case
