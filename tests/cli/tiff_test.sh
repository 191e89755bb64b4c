#!/usr/bin/env bash
# End-to-end: microscopy TIFFs (ImageJ hyperstacks, OME-TIFF, plain pages, folders) written by
# tifffile through `tstyles info`, `convert`, `render` and `view`; damaged files and impossible
# options end in exit code 2, one line naming the file, the field and the problem, nothing written.
# Usage: tiff_test.sh TSTYLES SOURCE_DIR SCRATCH_ROOT CASE (see cli_test_lib.sh); PYTHON is a Python
# with tifffile and numpy (CMake passes the one it found).
source "$(dirname "${BASH_SOURCE[0]}")/cli_test_lib.sh"

PYTHON=${PYTHON:-python3}

# The files write_tiff_samples.py describes, with the values its functions give.
samples() {
    S="$SCRATCH/samples"
    "$PYTHON" "$SOURCE_DIR/tests/cli/write_tiff_samples.py" "$S" || fail "write_tiff_samples.py failed"
}

# The float32 (little-endian, as the manifest's raw files are) at value index $2 of file $1.
float_at() {
    od -A n -t f4 -j $(($2 * 4)) -N 4 "$1" | tr -d ' '
}

expect_float_at() {
    local value
    value=$(float_at "$1" "$2")
    [ "$value" = "$3" ] || fail "$(basename "$1")[$2] is $value, expected $3"
}

# A bad file: exit 2, one error line naming FILE and FIELD with PROBLEM, and convert writes nothing.
expect_refused() {
    local file=$1 field=$2 problem=$3
    shift 3
    run_tstyles -- convert "$file" "$@" -o "$SCRATCH/out"
    expect_exit 2
    expect_error_line "$file" "$field" "$problem"
    [ ! -e "$SCRATCH/out" ] || fail "convert failed but created $SCRATCH/out"
}

case_info_hyperstack() {
    samples
    run_tstyles -- info "$S/hyperstack.tif"
    expect_exit 0
    expect_stdout_contains "Format: ImageJ hyperstack TIFF"
    expect_stdout_contains "Read: channel 0 of 2 (the first; --channel N takes another)"
    expect_stdout_contains "Read: ImageJ hyperstack: 2 channel(s) x 4 slices x 3 frames"
    expect_stdout_contains "Read: image rows run top-down"
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "Value range: [0, 2345]"
    expect_stdout_contains "(0.2, 0.2, 0.5)"
    expect_stdout_contains "x = x (um, unknown), y = y (um, unknown), z = z (um, unknown)"
    expect_stdout_contains "Time: seconds"
    expect_stdout_contains "60 s"
}

# Channel 1 is channel 0 plus 5000; the values of step 1 come back as written (x fastest, in the
# file's row and slice order: the turn is in the placement, not in the values).
case_channel_values() {
    samples
    run_tstyles -- convert "$S/hyperstack.tif" --channel 1 -o "$SCRATCH/out"
    expect_exit 0
    # t=1, z=1, y=3, x=2: 1000 + 100 + 30 + 2 + 5000.
    expect_float_at "$SCRATCH/out/t01.raw" $((2 + 6 * 3 + 30 * 1)) 6132
    expect_float_at "$SCRATCH/out/t02.raw" 0 7000
    run_tstyles -- info "$S/hyperstack.tif" --channel 1
    expect_exit 0
    expect_stdout_contains "Read: channel 1 of 2 (--channel)"
    expect_stdout_contains "Value range: [5000, 7345]"
}

case_contiguous_imagej() {
    samples
    run_tstyles -- convert "$S/contiguous.tif" -o "$SCRATCH/out"
    expect_exit 0
    expect_float_at "$SCRATCH/out/t02.raw" $((5 + 6 * 4 + 30 * 3)) 2345
    run_tstyles -- info "$S/contiguous.tif"
    expect_stdout_contains "one run of data without IFDs"
}

case_info_ome() {
    samples
    run_tstyles -- info "$S/tzyx.ome.tif"
    expect_exit 0
    expect_stdout_contains "Format: OME-TIFF"
    expect_stdout_contains "Read: OME-XML: 4 z x 1 c x 3 t, DimensionOrder XYCZT"
    expect_stdout_contains "Read: times from TimeIncrement (ms)"
    expect_stdout_contains "(0.25, 0.25, 1.5)"
    expect_stdout_contains "Time: milliseconds"
    expect_stdout_contains "4 ms"
    expect_stdout_contains "Value range: [-7, 172.5]"
}

# An OME-TIFF time-lapse split over files (one per time point, the TiffData naming each by UUID
# FileName): any one of them opens the whole series, values as written. Without one of the files,
# the error names the TiffData.
case_ome_across_files() {
    samples
    run_tstyles -- info "$S/lapse_t0.ome.tif"
    expect_exit 0
    expect_stdout_contains "Read: planes in 3 files named by the OME-XML's TiffData"
    expect_stdout_contains "Time-steps: 3"
    expect_stdout_contains "Value range: [0, 2345]"
    expect_stdout_contains "2  2 min"
    run_tstyles -- convert "$S/lapse_t1.ome.tif" -o "$SCRATCH/out"
    expect_exit 0
    expect_float_at "$SCRATCH/out/t00.raw" 0 0
    expect_float_at "$SCRATCH/out/t01.raw" 7 1011
    expect_float_at "$SCRATCH/out/t02.raw" 119 2345
    rm -r "$S/lapse_t2.ome.tif" "$SCRATCH/out"
    expect_refused "$S/lapse_t0.ome.tif" "OME-XML TiffData UUID FileName" \
        "puts planes in \"lapse_t2.ome.tif\", which is not beside this file"
}

# An OME-TIFF pyramid (tifffile, SubIFDs): the full resolution by default, --level 1 and 2 read the
# halved and quartered planes with the spacing grown to match; a level past the pyramid, or --level
# on a TIFF without one, is refused.
case_ome_pyramid_level() {
    samples
    run_tstyles -- info "$S/pyramid.ome.tif"
    expect_exit 0
    expect_stdout_contains "Read: resolution level 0 of 3 (SubIFDs): 20 x 16 pixels a plane (the full resolution; --level chooses another)"
    expect_stdout_contains "rectilinear 20x16x3"
    run_tstyles -- info "$S/pyramid.ome.tif" --level 2
    expect_exit 0
    expect_stdout_contains "Read: resolution level 2 of 3 (SubIFDs): 5 x 4 pixels a plane (--level)"
    expect_stdout_contains "rectilinear 5x4x3"
    expect_stdout_contains "(1, 1, 1)"
    run_tstyles -- convert "$S/pyramid.ome.tif" --level 1 -o "$SCRATCH/out"
    expect_exit 0
    # Level 1 is every other pixel: its (x, y) = (3, 2) is the full (6, 4): t 1, z 2 gives 1000 + 200 + 20 + 6.
    expect_float_at "$SCRATCH/out/t01.raw" $((3 + 10 * (2 + 8 * 2))) 1226
    run_tstyles -- info "$S/pyramid.ome.tif" --level 3
    expect_exit 2
    expect_error_line "$S/pyramid.ome.tif" "--level" "is 3: this OME-TIFF has 3 resolution levels (0 to 2, in its planes' SubIFDs)"
    run_tstyles -- info "$S/hyperstack.tif" --level 1
    expect_exit 2
    expect_error_line "$S/hyperstack.tif" "--level" "chooses a level of an OME-TIFF pyramid (SubIFDs); this ImageJ file has one resolution"
}

# NaN over land in a float OME-TIFF is missing data: counted, out of the range, NaN in what convert
# writes, transparent in the picture (TIFF has no missing-value marker). Sizes in km and m.
case_nan_over_land() {
    samples
    run_tstyles -- info "$S/ocean.ome.tif"
    expect_exit 0
    expect_stdout_contains "Missing values: 288 voxels without data (30.0 %)"
    expect_stdout_contains "Value range: [14.15, 20.65]"
    expect_stdout_contains "(2, 2, 0.005)"  # 5 m between slices, in the x size's kilometres
    run_tstyles -- convert "$S/ocean.ome.tif" -o "$SCRATCH/out"
    expect_exit 0
    expect_float_at "$SCRATCH/out/t00.raw" 0 nan
    expect_float_at "$SCRATCH/out/t00.raw" 2 nan
    expect_float_at "$SCRATCH/out/t00.raw" 3 20.15
    expect_float_at "$SCRATCH/out/t02.raw" 319 14.65
    run_tstyles -- render "$S/ocean.ome.tif" -o "$SCRATCH/ocean.png" --backend osmesa --width 64 --height 64
    expect_exit 0
}

# Three int16 channels as planes; z in nanometres becomes micrometres; times from the Planes.
case_ome_channel_delta_t() {
    samples
    run_tstyles -- info "$S/tzcyx.ome.tif" --channel 2
    expect_exit 0
    expect_stdout_contains "Read: channel 2 of 3 (--channel)"
    expect_stdout_contains "Read: times from the Planes' DeltaT (s)"
    expect_stdout_contains "(0.2, 0.2, 0.8)"
    expect_stdout_contains "1.5 s"
    expect_stdout_contains "Value range: [1600, 2115]"
    run_tstyles -- convert "$S/tzcyx.ome.tif" --channel 2 -o "$SCRATCH/out"
    expect_exit 0
    # t=2, z=3, y=4, x=5: 400 + 90 + 20 + 5 - 400 + 2000.
    expect_float_at "$SCRATCH/out/t02.raw" 119 2115
}

case_tiled_deflate() {
    samples
    run_tstyles -- convert "$S/tiled.ome.tif" -o "$SCRATCH/out"
    expect_exit 0
    # Step 1, z 2, y 35, x 39 (in the last, partial tile): flat index 1*3*36*40 + 2*36*40 + 35*40 + 39.
    local flat=$((4320 + 2880 + 1400 + 39))
    expect_float_at "$SCRATCH/out/t01.raw" $((2880 + 1400 + 39)) $(((flat * 7 % 256) - 128))
}

case_plain_one_volume() {
    samples
    run_tstyles -- info "$S/plain.tif"
    expect_exit 0
    expect_stdout_contains "Format: TIFF"
    expect_stdout_contains "Read: 12 pages read as one volume (every page a z-slice); --dims NXxNYxNZ and --axes"
    expect_stdout_contains "Time-steps: 1"
}

case_plain_dims_axes() {
    samples
    run_tstyles -- convert "$S/plain.tif" --dims 6x5x4 -o "$SCRATCH/tzyx"
    expect_exit 0
    # TZYX: step 2, slice 1 is page 9.
    expect_float_at "$SCRATCH/tzyx/t02.raw" 30 $((9 * 30 * 3))
    run_tstyles -- convert "$S/plain.tif" --dims 6x5x4 --axes ZTYX -o "$SCRATCH/ztyx"
    expect_exit 0
    # ZTYX: step 2, slice 1 is page 1 * 3 + 2 = 5.
    expect_float_at "$SCRATCH/ztyx/t02.raw" 30 $((5 * 30 * 3))
    run_tstyles -- info "$S/plain.tif" --dims 6x5x4 --axes ZTYX
    expect_stdout_contains "Read: 12 pages as 3 time-steps of 4 slices, z slowest (ZTYX)"
}

# t1, t2, t10: natural order, so t10.tif (values from 100) is the last step.
case_folder_of_volumes() {
    samples
    run_tstyles -- convert "$S/steps" -o "$SCRATCH/out"
    expect_exit 0
    expect_float_at "$SCRATCH/out/t02.raw" 0 100
    expect_float_at "$SCRATCH/out/t01.raw" 0 50
    run_tstyles -- info "$S/steps"
    expect_stdout_contains "Format: TIFF (3 files)"
    expect_stdout_contains "Time-steps: 3"
}

case_folder_of_slices() {
    samples
    run_tstyles -- info "$S/slices"
    expect_exit 0
    expect_stdout_contains "Read: 5 pages read as one volume"
    expect_stdout_contains "Value range: [0, 7.625]"
}

# Samples per pixel as channels, interleaved or planar: the same values.
case_rgb_channels() {
    samples
    run_tstyles -- convert "$S/rgb.tif" --channel 2 -o "$SCRATCH/contiguous"
    expect_exit 0
    run_tstyles -- convert "$S/rgb_planar.tif" --channel 2 -o "$SCRATCH/planar"
    expect_exit 0
    cmp -s "$SCRATCH/contiguous/t00.raw" "$SCRATCH/planar/t00.raw" || fail "planar and interleaved samples differ"
    # z 3, y 4, x 5, sample 2: 60 + 20 + 5 + 120.
    expect_float_at "$SCRATCH/planar/t00.raw" 119 205
    run_tstyles -- info "$S/rgb.tif" --channel 2
    expect_stdout_contains "Read: channel 2 of 3 (--channel)"
}

# The same series as NIfTI (no orientation, rows and slices reversed as the reader turns them):
# the same picture, to the byte.
case_same_as_nifti() {
    samples
    run_tstyles -- render "$S/hyperstack.tif" -o "$SCRATCH/tiff.png" --backend osmesa --width 96 --height 96
    expect_exit 0
    run_tstyles -- render "$S/hyperstack_c0.nii" -o "$SCRATCH/nifti.png" --backend osmesa --width 96 --height 96
    expect_exit 0
    expect_image "$SCRATCH/tiff.png" 96 96
    cmp -s "$SCRATCH/tiff.png" "$SCRATCH/nifti.png" || fail "the TIFF and the NIfTI of one series render differently"
}

case_view_hyperstack() {
    have_xvfb || return 0
    samples
    view_and_screenshot "$S/hyperstack.tif" --size 640x480
}

case_strip_cut_short() {
    samples
    expect_refused "$S/bad/strip_cut.tif" "page 3" "strip 0 is cut short"
}

case_truncated_file() {
    samples
    expect_refused "$S/bad/truncated.tif" "page 7" "cannot be read (libtiff: TIFFReadDirectory"
}

case_imagej_images_mismatch() {
    samples
    expect_refused "$S/bad/images_mismatch.tif" "ImageDescription images=" "says 26 images, but channels x slices x frames"
}

case_ome_sizes_mismatch() {
    samples
    expect_refused "$S/bad/ome_sizes.ome.tif" "OME-XML Pixels" "36 planes, the file has only 12 IFDs"
}

case_unknown_compression() {
    samples
    expect_refused "$S/bad/compression.tif" "page 0 Compression" "is 40000, a compression this libtiff cannot decode"
}

case_channel_out_of_range() {
    samples
    expect_refused "$S/hyperstack.tif" "--channel" "2 is out of range: the image has 2 channels (0 to 1)" --channel 2
}

case_no_z_axis() {
    samples
    expect_refused "$S/bad/no_z.tif" "ImageDescription slices=" "a volume needs at least 2 along x, y and z"
}

case_unsupported_samples() {
    samples
    expect_refused "$S/bad/float16.tif" "page 0 BitsPerSample" "16-bit float samples are not supported"
    expect_refused "$S/bad/one_bit.tif" "page 0 BitsPerSample" "1-bit integer samples are not supported"
    expect_refused "$S/bad/complex.tif" "page 0 SampleFormat" "complex samples are not supported"
    expect_refused "$S/bad/palette.tif" "page 0 PhotometricInterpretation" "is a palette image"
}

case_pages_of_different_sizes() {
    samples
    expect_refused "$S/bad/mixed_sizes.tif" "page 2" "the pages of a volume must agree"
}

case_bad_page_options() {
    samples
    expect_refused "$S/plain.tif" "--dims" "5 slices a volume do not divide the 12 pages" --dims 6x5x5
    expect_refused "$S/plain.tif" "--dims" "gives 7 x 5 samples a slice, the pages are 6 x 5" --dims 7x5x4
    expect_refused "$S/plain.tif" "--axes" "is not a page order of a volume over time" --dims 6x5x4 --axes TYXZ
    expect_refused "$S/plain.tif" "--axes" "needs --dims" --axes ZTYX
    expect_refused "$S/hyperstack.tif" "--dims" "this ImageJ file says its own layout" --dims 6x5x4
}

run_case
