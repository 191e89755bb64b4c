"""Small DICOM series written with pydicom for the DICOM reader's tests (tests/cli/dicom_test.sh,
tests/python/test_dicom.py), every value given by a closed form so that the tests know what must come
back. Run as a script: dicom_samples.py FOLDER [NAME...] writes the named samples (all by default).
"""

import math
import os
import random
import sys

import numpy as np
from pydicom.dataset import Dataset, FileMetaDataset
from pydicom.sequence import Sequence
from pydicom.uid import ExplicitVRLittleEndian, PYDICOM_IMPLEMENTATION_UID

MR_IMAGE = "1.2.840.10008.5.1.4.1.1.4"
CT_IMAGE = "1.2.840.10008.5.1.4.1.1.2"
ENHANCED_MR_IMAGE = "1.2.840.10008.5.1.4.1.1.4.1"
UID_ROOT = "1.2.826.0.1.3680043.10.1187."  # a root for test UIDs; any syntactically valid one would do

# The 4D cine: 4 time-steps of 6 slices of 16 x 12 pixels, oblique.
CINE_DIMS = (16, 12, 6)
CINE_STEPS = 4
CINE_SPACING = (0.6, 0.8, 2.5)        # between columns, between rows, between slices (mm)
CINE_ORIGIN = (-10.0, 20.0, 30.0)     # LPS mm
CINE_TRIGGER_MS = 40.0
CINE_UID = UID_ROOT + "5"
SCOUT_UID = UID_ROOT + "1"


def cine_value(t, z, y, x):
    return t * 1000 + z * 200 + y * 16 + x


def cine_cosines():
    """Row and column direction cosines (LPS) of the oblique cine, as written (10 decimals)."""
    a, b = math.radians(30.0), math.radians(20.0)
    row = [math.cos(a), math.sin(a), 0.0]
    column = [-math.sin(a) * math.cos(b), math.cos(a) * math.cos(b), math.sin(b)]
    return [round(v, 10) for v in row], [round(v, 10) for v in column]


# The CT: one volume of 4 uneven slices of 10 x 8, int16 stored, HU = stored - 1024.
CT_DIMS = (10, 8, 4)
CT_SLICE_Z = (0.0, 1.25, 2.5, 5.0)


def ct_stored(z, y, x):
    return x * 7 + y * 13 + z * 100 - 50


# The enhanced multi-frame file: 3 time-steps of 4 sagittal slices of 8 x 6, rescaled.
ENH_DIMS = (8, 6, 4)
ENH_STEPS = 3
ENH_SLOPE, ENH_INTERCEPT = 0.5, 10.0
ENH_SECONDS = 2.5


def enhanced_stored(t, z, y, x):
    return t * 100 + z * 20 + y * 8 + x


# The RT Dose: one multi-frame file of 5 axial frames of 10 x 8, 32-bit stored, placed by
# GridFrameOffsetVector 3 mm apart; dose = stored x DoseGridScaling gray.
RTDOSE_STORAGE = "1.2.840.10008.5.1.4.1.1.481.2"
DOSE_DIMS = (10, 8, 5)
DOSE_ORIGIN = (-20.0, -15.0, 40.0)    # LPS mm
DOSE_OFFSETS = (0.0, 3.0, 6.0, 9.0, 12.0)
DOSE_SCALING = 0.001


def dose_stored(z, y, x):
    return z * 100 + y * 10 + x


def ds_text(value):
    return f"{value:.10g}"


def new_file(sop_class, sop_instance, series_uid, series_number, description, modality):
    meta = FileMetaDataset()
    meta.MediaStorageSOPClassUID = sop_class
    meta.MediaStorageSOPInstanceUID = sop_instance
    meta.TransferSyntaxUID = ExplicitVRLittleEndian
    meta.ImplementationClassUID = PYDICOM_IMPLEMENTATION_UID
    ds = Dataset()
    ds.file_meta = meta
    ds.is_little_endian = True
    ds.is_implicit_VR = False
    ds.SOPClassUID = sop_class
    ds.SOPInstanceUID = sop_instance
    ds.StudyInstanceUID = UID_ROOT + "100"
    ds.SeriesInstanceUID = series_uid
    ds.SeriesNumber = series_number
    ds.SeriesDescription = description
    ds.Modality = modality
    ds.PatientName = "Phantom^Test"
    ds.PatientID = "TS-0001"
    return ds


def set_pixels(ds, pixels, signed=False, bits_stored=None):
    """pixels: (frames, rows, columns) or (rows, columns) integer array."""
    pixels = np.asarray(pixels, dtype=np.int16 if signed else np.uint16)
    ds.Rows, ds.Columns = pixels.shape[-2], pixels.shape[-1]
    ds.SamplesPerPixel = 1
    ds.PhotometricInterpretation = "MONOCHROME2"
    ds.BitsAllocated = 16
    ds.BitsStored = bits_stored or 16
    ds.HighBit = ds.BitsStored - 1
    ds.PixelRepresentation = 1 if signed else 0
    ds.PixelData = pixels.astype("<i2" if signed else "<u2").tobytes()


def save(ds, path):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    ds.save_as(path, write_like_original=False)


def cine_slice(t, z, number):
    row, column = cine_cosines()
    normal = np.cross(row, column)
    position = np.array(CINE_ORIGIN) + z * CINE_SPACING[2] * normal
    ds = new_file(MR_IMAGE, f"{CINE_UID}.{t}.{z}", CINE_UID, 5, "cine short axis", "MR")
    ds.ImagePositionPatient = [ds_text(v) for v in position]
    ds.ImageOrientationPatient = [ds_text(v) for v in row + column]
    ds.PixelSpacing = [ds_text(CINE_SPACING[1]), ds_text(CINE_SPACING[0])]
    ds.SliceThickness = ds_text(CINE_SPACING[2])
    ds.TemporalPositionIdentifier = t + 1
    ds.TriggerTime = ds_text(t * CINE_TRIGGER_MS)
    ds.AcquisitionTime = f"1200{z:02d}.{t:06d}"  # differs per slice: the temporal tags must win
    ds.InstanceNumber = number
    nx, ny, _ = CINE_DIMS
    set_pixels(ds, [[cine_value(t, z, y, x) for x in range(nx)] for y in range(ny)])
    return ds


def write_cine(folder):
    """The 4D cine under shuffled names without extension (some in a nested folder), a 3-slice
    scout series (SeriesNumber 1) beside it, and a README that is not DICOM."""
    names = list(range(CINE_STEPS * CINE_DIMS[2]))
    random.Random(37).shuffle(names)
    for t in range(CINE_STEPS):
        for z in range(CINE_DIMS[2]):
            index = t * CINE_DIMS[2] + z
            sub = "sub" if index % 3 == 0 else ""
            save(cine_slice(t, z, CINE_STEPS * CINE_DIMS[2] - index), os.path.join(folder, sub, f"IM{names[index]:04d}"))
    for z in range(3):
        ds = new_file(MR_IMAGE, f"{SCOUT_UID}.{z}", SCOUT_UID, 1, "scout", "MR")
        ds.ImagePositionPatient = ["0", "0", ds_text(z * 5.0)]
        ds.ImageOrientationPatient = ["1", "0", "0", "0", "1", "0"]
        ds.PixelSpacing = ["2", "2"]
        set_pixels(ds, np.full((8, 8), z + 1))
        save(ds, os.path.join(folder, f"SC{z}"))
    with open(os.path.join(folder, "README"), "w") as readme:
        readme.write("not DICOM\n")


def write_ct(folder):
    uid = UID_ROOT + "7"
    nx, ny, nz = CT_DIMS
    for z in range(nz):
        ds = new_file(CT_IMAGE, f"{uid}.{z}", uid, 2, "chest", "CT")
        ds.ImagePositionPatient = ["-5", "-4", ds_text(CT_SLICE_Z[z])]
        ds.ImageOrientationPatient = ["1", "0", "0", "0", "1", "0"]
        ds.PixelSpacing = ["0.5", "0.5"]
        ds.RescaleIntercept = "-1024"
        ds.RescaleSlope = "1"
        set_pixels(ds, [[ct_stored(z, y, x) for x in range(nx)] for y in range(ny)], signed=True)
        save(ds, os.path.join(folder, f"ct{z}.dcm"))


def item(**elements):
    entry = Dataset()
    for key, value in elements.items():
        setattr(entry, key, value)
    return entry


def write_enhanced(path):
    """Frames time-major, slices written from the last to the first; per-frame positions, times and
    rescale; shared orientation and spacing (sagittal: rows toward posterior, columns toward feet)."""
    uid = UID_ROOT + "9"
    nx, ny, nz = ENH_DIMS
    ds = new_file(ENHANCED_MR_IMAGE, uid + ".1", uid, 7, "enhanced perfusion", "MR")
    ds.NumberOfFrames = ENH_STEPS * nz
    ds.SharedFunctionalGroupsSequence = Sequence([item(
        PixelMeasuresSequence=Sequence([item(PixelSpacing=["1.5", "1"], SliceThickness="2")]),
        PlaneOrientationSequence=Sequence([item(ImageOrientationPatient=["0", "1", "0", "0", "0", "-1"])]))])
    frames, pixels = [], []
    for t in range(ENH_STEPS):
        for z in reversed(range(nz)):
            # The normal of these cosines is -x (LPS): slice z lies 2 mm further toward the patient's right.
            frames.append(item(
                PlanePositionSequence=Sequence([item(ImagePositionPatient=[ds_text(-2.0 * z), "10", "40"])]),
                FrameContentSequence=Sequence([item(
                    TemporalPositionIndex=t + 1,
                    FrameAcquisitionDateTime=f"20240101120{int(t * ENH_SECONDS):03d}.{int(t * ENH_SECONDS * 10) % 10}")]),
                PixelValueTransformationSequence=Sequence([item(
                    RescaleIntercept=ds_text(ENH_INTERCEPT), RescaleSlope=ds_text(ENH_SLOPE), RescaleType="US")])))
            pixels.append([[enhanced_stored(t, z, y, x) for x in range(nx)] for y in range(ny)])
    ds.PerFrameFunctionalGroupsSequence = Sequence(frames)
    set_pixels(ds, pixels, bits_stored=12)
    save(ds, path)


# The multi-phase CT: three contrast phases of one study, each its own series of 5 axial slices of
# 12 x 10 (0.7 mm pixels, 2 mm apart), written out of acquisition order (SeriesNumber 3 arterial at
# 12:00:20, 4 delayed at 12:03:00, 5 portal venous at 12:01:10); HU = stored - 1024 with stored =
# 1024 + phase_value(phase, z, y, x). Beside them: a scout (SeriesNumber 1, another grid) and the
# arterial phase again with a lung kernel (SeriesNumber 2: another ConvolutionKernel, never a phase).
PHASE_DIMS = (12, 10, 5)
PHASES = ((3, "arterial", "120020", 0), (4, "delayed", "120300", 2), (5, "portal venous", "120110", 1))


def phase_value(phase, z, y, x):
    """HU of phase 0 (arterial), 1 (portal venous), 2 (delayed): a liver that enhances late."""
    return 40 + 30 * phase + z * 5 + y * 2 + x - 12


def write_phases(folder):
    frame_of_reference = UID_ROOT + "15.0"
    nx, ny, nz = PHASE_DIMS
    for number, description, time, phase in PHASES + ((2, "arterial lung", "120020", 0),):
        uid = f"{UID_ROOT}15.{number}"
        for z in range(nz):
            ds = new_file(CT_IMAGE, f"{uid}.{z}", uid, number, description, "CT")
            ds.FrameOfReferenceUID = frame_of_reference
            ds.ImagePositionPatient = ["-4", "-3.5", ds_text(100.0 + 2.0 * z)]
            ds.ImageOrientationPatient = ["1", "0", "0", "0", "1", "0"]
            ds.PixelSpacing = ["0.7", "0.7"]
            ds.SliceThickness = "2"
            ds.KVP = "120"
            ds.ConvolutionKernel = "B70f" if number == 2 else "B30f"
            ds.ImageType = ["ORIGINAL", "PRIMARY", "AXIAL"]
            ds.AcquisitionDate = "20240301"
            ds.AcquisitionTime = f"{time}.{z}"  # a tenth of a second per slice
            ds.InstanceNumber = z + 1
            ds.RescaleIntercept = "-1024"
            ds.RescaleSlope = "1"
            set_pixels(ds, [[1024 + phase_value(phase, z, y, x) for x in range(nx)] for y in range(ny)])
            save(ds, os.path.join(folder, f"s{number}", f"im{z}"))
    uid = UID_ROOT + "15.1"
    for z in range(3):
        ds = new_file(CT_IMAGE, f"{uid}.{z}", uid, 1, "scout", "CT")
        ds.FrameOfReferenceUID = frame_of_reference
        ds.ImagePositionPatient = ["0", "0", ds_text(z * 20.0)]
        ds.ImageOrientationPatient = ["1", "0", "0", "0", "1", "0"]
        ds.PixelSpacing = ["2", "2"]
        ds.AcquisitionDate = "20240301"
        ds.AcquisitionTime = "115900"
        set_pixels(ds, np.full((8, 8), z + 1))
        save(ds, os.path.join(folder, "scout", f"im{z}"))


def write_abdomen_phases(folder, size=96, slices=32):
    """A realistic multi-phase abdominal CT for the documentation: a body with fat, muscle, spine,
    aorta, liver, spleen and kidneys (0.8 mm pixels, 3 mm slices), scanned three times after one
    contrast injection, one series a phase: arterial (aorta bright, 25 s), portal venous (liver and
    spleen enhanced, 70 s), delayed (kidneys' collecting systems bright, 180 s); with noise."""
    frame_of_reference = UID_ROOT + "17.0"
    rng = np.random.default_rng(17)
    z, y, x = np.indices((slices, size, size)).astype(float)
    c = size / 2.0
    body = ((x - c) / (0.45 * size)) ** 2 + ((y - c) / (0.34 * size)) ** 2 < 1
    fat_rim = body & ~(((x - c) / (0.41 * size)) ** 2 + ((y - c) / (0.30 * size)) ** 2 < 1)
    spine = ellipsoid((slices, size, size), (c, c + 0.2 * size, slices / 2), (0.07 * size, 0.07 * size, slices))
    aorta = ellipsoid((slices, size, size), (c - 0.05 * size, c + 0.08 * size, slices / 2), (0.04 * size, 0.04 * size, slices))
    liver = ellipsoid((slices, size, size), (c - 0.2 * size, c - 0.02 * size, slices * 0.6),
                      (0.17 * size, 0.2 * size, slices * 0.45)) & body
    spleen = ellipsoid((slices, size, size), (c + 0.28 * size, c + 0.05 * size, slices * 0.65),
                       (0.07 * size, 0.09 * size, slices * 0.25)) & body
    kidneys = (ellipsoid((slices, size, size), (c - 0.17 * size, c + 0.15 * size, slices * 0.35),
                         (0.045 * size, 0.06 * size, slices * 0.2)) |
               ellipsoid((slices, size, size), (c + 0.17 * size, c + 0.15 * size, slices * 0.35),
                         (0.045 * size, 0.06 * size, slices * 0.2)))
    collecting = kidneys & (np.abs(np.abs(x - c) - 0.17 * size) < 0.015 * size)
    phases = ((3, "arterial", "141025", {"aorta": 320, "liver": 70, "spleen": 120, "kidney": 180, "collect": 40}),
              (4, "portal venous", "141110", {"aorta": 160, "liver": 130, "spleen": 130, "kidney": 170, "collect": 60}),
              (5, "delayed", "141300", {"aorta": 90, "liver": 90, "spleen": 90, "kidney": 110, "collect": 400}))
    for number, description, time, hu in phases:
        values = np.full(z.shape, -1000.0)
        values[body] = 45.0
        values[fat_rim] = -100.0
        values[liver] = hu["liver"]
        values[spleen] = hu["spleen"]
        values[kidneys] = hu["kidney"]
        values[collecting] = hu["collect"]
        values[aorta] = hu["aorta"]
        values[spine] = 600.0
        values += rng.normal(0.0, 12.0, values.shape) * body
        uid = f"{UID_ROOT}17.{number}"
        for k in range(slices):
            ds = new_file(CT_IMAGE, f"{uid}.{k}", uid, number, description, "CT")
            ds.FrameOfReferenceUID = frame_of_reference
            ds.ImagePositionPatient = [ds_text(-0.4 * size), ds_text(-0.4 * size), ds_text(-60.0 + 3.0 * k)]
            ds.ImageOrientationPatient = ["1", "0", "0", "0", "1", "0"]
            ds.PixelSpacing = ["0.8", "0.8"]
            ds.SliceThickness = "3"
            ds.KVP = "120"
            ds.ConvolutionKernel = "B30f"
            ds.AcquisitionDate = "20240301"
            ds.AcquisitionTime = f"{time}.{k:02d}"
            ds.InstanceNumber = k + 1
            ds.RescaleIntercept = "-1024"
            ds.RescaleSlope = "1"
            set_pixels(ds, np.clip(np.round(values[k] + 1024), 0, 4095), bits_stored=12)
            save(ds, os.path.join(folder, f"series{number}", f"im{k:03d}"))


def write_rt_dose(path, absolute=False, orientation=("1", "0", "0", "0", "1", "0")):
    """As a treatment planning system exports it: no functional groups, frame positions from
    GridFrameOffsetVector, from the first frame (0, 3, ...) or, with `absolute`, as z coordinates."""
    uid = UID_ROOT + "13"
    nx, ny, nz = DOSE_DIMS
    ds = new_file(RTDOSE_STORAGE, uid + ".1", uid, 3, "dose", "RTDOSE")
    ds.NumberOfFrames = nz
    ds.FrameIncrementPointer = 0x3004000C
    ds.ImagePositionPatient = [ds_text(v) for v in DOSE_ORIGIN]
    ds.ImageOrientationPatient = list(orientation)
    ds.PixelSpacing = ["2.5", "2"]
    ds.SliceThickness = ""
    first = DOSE_ORIGIN[2] if absolute else 0.0
    ds.GridFrameOffsetVector = [ds_text(first + offset) for offset in DOSE_OFFSETS]
    ds.DoseUnits = "GY"
    ds.DoseType = "PHYSICAL"
    ds.DoseSummationType = "PLAN"
    ds.DoseGridScaling = ds_text(DOSE_SCALING)
    pixels = np.array([[[dose_stored(z, y, x) for x in range(nx)] for y in range(ny)] for z in range(nz)])
    ds.Rows, ds.Columns = ny, nx
    ds.SamplesPerPixel = 1
    ds.PhotometricInterpretation = "MONOCHROME2"
    ds.BitsAllocated = 32
    ds.BitsStored = 32
    ds.HighBit = 31
    ds.PixelRepresentation = 0
    ds.PixelData = pixels.astype("<u4").tobytes()
    save(ds, path)


# The head-up phantom: axial slices, feet (first slice) dark, head (last slice) bright.
HEAD_DIMS = (16, 16, 12)


def write_head_up(folder):
    uid = UID_ROOT + "11"
    nx, ny, nz = HEAD_DIMS
    for z in range(nz):
        ds = new_file(MR_IMAGE, f"{uid}.{z}", uid, 3, "head up", "MR")
        ds.ImagePositionPatient = ["-8", "-8", ds_text(z * 2.0)]
        ds.ImageOrientationPatient = ["1", "0", "0", "0", "1", "0"]
        ds.PixelSpacing = ["1", "1"]
        set_pixels(ds, np.full((ny, nx), 100 + 300 * z))
        save(ds, os.path.join(folder, f"head{z:02d}.dcm"))


def ellipsoid(shape, centre, radii):
    z, y, x = np.indices(shape, dtype=np.float64)
    return ((x - centre[0]) / radii[0]) ** 2 + ((y - centre[1]) / radii[1]) ** 2 + ((z - centre[2]) / radii[2]) ** 2 <= 1


def write_cardiac_perfusion(folder, steps=8, size=64, slices=24):
    """A realistic first-pass perfusion series: a torso (1.5 mm pixels) with dark lungs and a spine;
    a contrast bolus reaches the right ventricle first, then the left ventricle, then the
    myocardium around it. 8 time-steps 3 s apart (AcquisitionTime), axial slices from the feet up,
    one file a slice."""
    uid = UID_ROOT + "13"
    shape = (slices, size, size)
    c = size / 2
    torso = ellipsoid(shape, (c, c, slices / 2), (size * 0.45, size * 0.32, slices * 0.9))
    lungs = (ellipsoid(shape, (c - 16, c - 2, slices / 2), (9, 13, slices * 0.6)) |
             ellipsoid(shape, (c + 17, c - 2, slices / 2), (8, 13, slices * 0.6)))
    spine = ellipsoid(shape, (c, size * 0.76, slices / 2), (4, 4, slices))
    # The left ventricle toward the patient's left (LPS +x, higher column), the right one in front of
    # it toward the patient's right; the myocardium a shell around the left ventricle.
    myocardium = ellipsoid(shape, (c + 7, c - 3, slices / 2), (11, 10, 8))
    left_pool = ellipsoid(shape, (c + 7, c - 3, slices / 2), (6, 5.5, 5))
    right_pool = ellipsoid(shape, (c - 4, c - 9, slices / 2), (6, 4, 6)) & ~myocardium

    def bolus(step, peak):
        return math.exp(-((step - peak) / 1.2) ** 2)

    number = 1
    for step in range(steps):
        volume = np.where(torso, 60, 0)
        volume = np.where(lungs, 10, volume)
        volume = np.where(spine, 200, volume)
        volume = np.where(myocardium, 150 + 450 * bolus(step, 5), volume)
        volume = np.where(left_pool, 150 + 850 * bolus(step, 3), volume)
        volume = np.where(right_pool, 150 + 850 * bolus(step, 1), volume)
        for z in range(slices):
            ds = new_file(MR_IMAGE, f"{uid}.{step}.{z}", uid, 4, "first-pass perfusion (phantom)", "MR")
            ds.ImagePositionPatient = [ds_text(-size * 0.75), ds_text(-size * 0.75), ds_text(z * 4.0)]
            ds.ImageOrientationPatient = ["1", "0", "0", "0", "1", "0"]
            ds.PixelSpacing = ["1.5", "1.5"]
            ds.SliceThickness = "4"
            ds.AcquisitionDate = "20261127"
            ds.AcquisitionTime = f"0930{step * 3:02d}.{z * 100:06d}"  # slices 0.1 s apart within a step
            ds.InstanceNumber = number
            number += 1
            set_pixels(ds, volume[z].round())
            save(ds, os.path.join(folder, f"{number:05d}"))


def write_cine_as_nifti(path):
    """The cine's values and geometry as a NIfTI-1 file (sform in RAS: DICOM's LPS with x and y
    negated), written here byte by byte so that the comparison does not go through our reader."""
    import struct
    nx, ny, nz = CINE_DIMS
    row, column = cine_cosines()
    normal = np.cross(row, column)
    ras = np.diag([-1.0, -1.0, 1.0])
    axes = [ras @ np.array(row) * CINE_SPACING[0], ras @ np.array(column) * CINE_SPACING[1],
            ras @ normal * CINE_SPACING[2]]
    origin = ras @ np.array(CINE_ORIGIN)
    header = bytearray(352)
    struct.pack_into("<i", header, 0, 348)
    struct.pack_into("<8h", header, 40, 4, nx, ny, nz, CINE_STEPS, 1, 1, 1)
    struct.pack_into("<hh", header, 70, 16, 32)  # float32
    struct.pack_into("<8f", header, 76, 1.0, *CINE_SPACING, CINE_TRIGGER_MS, 1.0, 1.0, 1.0)
    struct.pack_into("<fff", header, 108, 352.0, 1.0, 0.0)
    header[123] = 2 | 16  # mm, ms
    struct.pack_into("<hh", header, 252, 0, 1)  # sform only
    for index in range(3):
        struct.pack_into("<4f", header, 280 + 16 * index, axes[0][index], axes[1][index], axes[2][index], origin[index])
    header[344:348] = b"n+1\0"
    values = np.array([[[[cine_value(t, z, y, x) for x in range(nx)] for y in range(ny)] for z in range(nz)]
                       for t in range(CINE_STEPS)], dtype="<f4")
    with open(path, "wb") as out:
        out.write(bytes(header) + values.tobytes())


def write_fuzz_seeds(folder):
    """Seeds of tests/fuzz/corpus/dicom (each under 16 KiB): the enhanced file, an RLE-compressed
    and a deflated 2-frame enhanced file, one classic CT slice, and an RT Dose file placed by
    GridFrameOffsetVector."""
    write_rt_dose(os.path.join(folder, "seed-rtdose.dcm"))
    from pydicom.uid import DeflatedExplicitVRLittleEndian, RLELossless
    os.makedirs(folder, exist_ok=True)
    write_enhanced(os.path.join(folder, "seed-enhanced.dcm"))
    write_ct(os.path.join(folder, "ct"))
    os.replace(os.path.join(folder, "ct", "ct0.dcm"), os.path.join(folder, "seed-ct-slice.dcm"))
    for name in os.listdir(os.path.join(folder, "ct")):
        os.remove(os.path.join(folder, "ct", name))
    os.rmdir(os.path.join(folder, "ct"))
    uid = UID_ROOT + "21"
    ds = new_file(ENHANCED_MR_IMAGE, uid + ".1", uid, 1, "two frames", "MR")
    ds.NumberOfFrames = 2
    ds.SharedFunctionalGroupsSequence = Sequence([item(
        PixelMeasuresSequence=Sequence([item(PixelSpacing=["1", "1"])]),
        PlaneOrientationSequence=Sequence([item(ImageOrientationPatient=["1", "0", "0", "0", "1", "0"])]))])
    ds.PerFrameFunctionalGroupsSequence = Sequence(
        [item(PlanePositionSequence=Sequence([item(ImagePositionPatient=["0", "0", str(z)])])) for z in range(2)])
    set_pixels(ds, np.arange(2 * 8 * 8).reshape(2, 8, 8))
    ds.compress(RLELossless)
    save(ds, os.path.join(folder, "seed-rle.dcm"))
    ds.decompress()
    ds.file_meta.TransferSyntaxUID = DeflatedExplicitVRLittleEndian
    save(ds, os.path.join(folder, "seed-deflated.dcm"))


SAMPLES = {
    "cine": lambda out: write_cine(os.path.join(out, "cine")),
    "ct": lambda out: write_ct(os.path.join(out, "ct")),
    "enhanced": lambda out: write_enhanced(os.path.join(out, "enhanced.dcm")),
    "head_up": lambda out: write_head_up(os.path.join(out, "head_up")),
    "cine_nifti": lambda out: write_cine_as_nifti(os.path.join(out, "cine.nii")),
    "fuzz_seeds": lambda out: write_fuzz_seeds(out),
    "perfusion": lambda out: write_cardiac_perfusion(os.path.join(out, "perfusion")),
    "phases": lambda out: write_phases(os.path.join(out, "phases")),
    "abdomen_phases": lambda out: write_abdomen_phases(os.path.join(out, "abdomen")),
    "rtdose": lambda out: write_rt_dose(os.path.join(out, "rtdose", "dose.dcm")),
    "rtdose_absolute": lambda out: write_rt_dose(os.path.join(out, "rtdose_absolute", "dose.dcm"), absolute=True),
    "rtdose_oblique_absolute": lambda out: write_rt_dose(os.path.join(out, "rtdose_oblique", "dose.dcm"),
                                                         absolute=True, orientation=("1", "0", "0", "0", "0.6", "0.8")),
}

if __name__ == "__main__":
    out = sys.argv[1]
    for name in sys.argv[2:] or [name for name in SAMPLES if name not in ("perfusion", "abdomen_phases", "fuzz_seeds")]:
        SAMPLES[name](out)
