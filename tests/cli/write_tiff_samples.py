"""Small TIFF files, good and bad, written with tifffile (as the users' files are) for the tiff
CLI cases (tests/cli/tiff_test.sh) and the Python tests (tests/python/test_tiff.py).

Usage: python3 write_tiff_samples.py FOLDER. The arrays are functions of their indices, so a test
knows every value it should read back (see the functions below).
       python3 write_tiff_samples.py --time-lapse FILE [--ome]: a microscopy-like time-lapse (cells
moving and one dividing, 2 channels, 0.2 um x/y, 0.5 um z, 30 s frames) as an ImageJ hyperstack or
OME-TIFF, for trying the reader as a user and for the gallery (docs/readers/tiff.md).
"""
import os
import struct
import sys

import numpy as np
import tifffile


def hyperstack_values():
    """ImageJ TZCYX: 3 frames, 4 slices, 2 channels, 5 x 6; channel 1 is channel 0 plus 5000."""
    t, z, c, y, x = np.indices((3, 4, 2, 5, 6))
    return (t * 1000 + z * 100 + y * 10 + x + c * 5000).astype(np.uint16)


def ome_tzyx_values():
    return (np.arange(3 * 4 * 5 * 6, dtype=np.float32).reshape(3, 4, 5, 6) * 0.5 - 7.0)


def ome_tzcyx_values():
    """int16 with three channels; channel c adds 1000 * c."""
    t, z, c, y, x = np.indices((3, 4, 3, 5, 6))
    return (t * 200 + z * 30 + y * 5 + x - 400 + c * 1000).astype(np.int16)


def tiled_values():
    """int8, 40 x 36 pages in 16 x 16 tiles (the last row and column of tiles only partly inside)."""
    return ((np.arange(2 * 3 * 36 * 40) * 7 % 256) - 128).astype(np.int8).reshape(2, 3, 36, 40)


def plain_values():
    return (np.arange(12 * 5 * 6, dtype=np.uint16) * 3).reshape(12, 5, 6)


def folder_step_values(step):
    z, y, x = np.indices((4, 5, 6))
    return (50 * step + z * 10 + y + x).astype(np.uint8)


def slice_values(z):
    y, x = np.indices((5, 6))
    return (z * 1.5 + y * 0.25 + x * 0.125).astype(np.float32)


def ocean_values():
    """Sea temperature, TZYX float32 (3 x 4 x 8 x 10): 20 - 2 z + 0.1 t + 0.05 x degrees C, and NaN
    over land (x < 3 at every depth and time): 288 of 960 voxels, as a resampled float OME-TIFF
    carries them."""
    t, z, y, x = np.indices((3, 4, 8, 10))
    values = (20.0 - 2.0 * z + 0.1 * t + 0.05 * x).astype(np.float32)
    values[x < 3] = np.nan
    return values


def lapse_values(t):
    """Time point t of the time-lapse split over files: ZYX uint16 (4 x 5 x 6)."""
    z, y, x = np.indices((4, 5, 6))
    return (t * 1000 + z * 100 + y * 10 + x).astype(np.uint16)


def write_lapse_files(folder):
    """An OME-TIFF time-lapse split over files, one per time point, as Bio-Formats and microscope
    software write it: each file holds its time point's 4 planes and the whole OME-XML, whose
    TiffData name the files by UUID FileName."""
    names = [f"lapse_t{t}.ome.tif" for t in range(3)]
    uuids = [f"urn:uuid:2f6a1c3e-0000-4000-8000-00000000000{t}" for t in range(3)]
    tiff_data = "".join(f'<TiffData FirstT="{t}" IFD="0" PlaneCount="4"><UUID FileName="{names[t]}">{uuids[t]}</UUID>'
                        "</TiffData>" for t in range(3))
    for t in range(3):
        xml = ('<?xml version="1.0" encoding="UTF-8"?>'
               f'<OME xmlns="http://www.openmicroscopy.org/Schemas/OME/2016-06" UUID="{uuids[t]}">'
               '<Image ID="Image:0" Name="lapse"><Pixels ID="Pixels:0" DimensionOrder="XYZCT" Type="uint16" '
               'SizeX="6" SizeY="5" SizeZ="4" SizeC="1" SizeT="3" PhysicalSizeX="0.5" PhysicalSizeY="0.5" '
               'PhysicalSizeZ="2" TimeIncrement="60" TimeIncrementUnit="s">'
               f'<Channel ID="Channel:0:0" SamplesPerPixel="1"/>{tiff_data}</Pixels></Image></OME>')
        tifffile.imwrite(os.path.join(folder, names[t]), lapse_values(t), photometric="minisblack",
                         description=xml, metadata=None)


def pyramid_values():
    """The full resolution of the pyramid: TZYX uint16 (2 x 3 x 16 x 20), t * 1000 + z * 100 + y * 5 + x."""
    t, z, y, x = np.indices((2, 3, 16, 20))
    return (t * 1000 + z * 100 + y * 5 + x).astype(np.uint16)


def write_pyramid(path):
    """An OME-TIFF pyramid as tifffile writes one: the full planes, each with two SubIFDs holding
    it at a half and a quarter of the size (every other pixel of the level above)."""
    full = pyramid_values()
    with tifffile.TiffWriter(path, ome=True) as tif:
        tif.write(full, subifds=2, metadata={"axes": "TZYX", "PhysicalSizeX": 0.25, "PhysicalSizeY": 0.25,
                                             "PhysicalSizeZ": 1.0})
        tif.write(full[:, :, ::2, ::2], subfiletype=1)
        tif.write(full[:, :, ::4, ::4], subfiletype=1)


def rgb_values():
    z, y, x, s = np.indices((4, 5, 6, 3))
    return (z * 20 + y * 5 + x + s * 60).astype(np.uint8)


def write_good(folder):
    tifffile.imwrite(os.path.join(folder, "hyperstack.tif"), hyperstack_values(), imagej=True,
                     resolution=(1 / 0.2, 1 / 0.2),
                     metadata={"axes": "TZCYX", "spacing": 0.5, "unit": "um", "finterval": 30})
    tifffile.imwrite(os.path.join(folder, "tzyx.ome.tif"), ome_tzyx_values(),
                     metadata={"axes": "TZYX", "PhysicalSizeX": 0.25, "PhysicalSizeY": 0.25,
                               "PhysicalSizeZ": 1.5, "TimeIncrement": 2, "TimeIncrementUnit": "ms"})
    tifffile.imwrite(os.path.join(folder, "tzcyx.ome.tif"), ome_tzcyx_values(),
                     metadata={"axes": "TZCYX", "PhysicalSizeX": 0.2, "PhysicalSizeY": 0.2,
                               "PhysicalSizeZ": 800, "PhysicalSizeZUnit": "nm",
                               "Plane": {"DeltaT": [float(t) for t in (0, 1.5, 4) for _ in range(12)],
                                         "DeltaTUnit": ["s"] * 36}})
    tifffile.imwrite(os.path.join(folder, "tiled.ome.tif"), tiled_values(), tile=(16, 16), compression="zlib",
                     predictor=True, metadata={"axes": "TZYX"})
    tifffile.imwrite(os.path.join(folder, "plain.tif"), plain_values(), photometric="minisblack", metadata=None)
    write_lapse_files(folder)
    write_pyramid(os.path.join(folder, "pyramid.ome.tif"))
    tifffile.imwrite(os.path.join(folder, "ocean.ome.tif"), ocean_values(),
                     metadata={"axes": "TZYX", "PhysicalSizeX": 2.0, "PhysicalSizeXUnit": "km", "PhysicalSizeY": 2.0,
                               "PhysicalSizeYUnit": "km", "PhysicalSizeZ": 5.0, "PhysicalSizeZUnit": "m"})
    os.makedirs(os.path.join(folder, "steps"))
    for step, name in enumerate(("t1.tif", "t2.tif", "t10.tif")):
        tifffile.imwrite(os.path.join(folder, "steps", name), folder_step_values(step), photometric="minisblack",
                         metadata=None)
    os.makedirs(os.path.join(folder, "slices"))
    for z in range(5):
        tifffile.imwrite(os.path.join(folder, "slices", "z%d.tif" % z), slice_values(z), photometric="minisblack",
                         metadata=None)
    tifffile.imwrite(os.path.join(folder, "rgb.tif"), rgb_values(), photometric="rgb", metadata=None)
    tifffile.imwrite(os.path.join(folder, "rgb_planar.tif"), np.moveaxis(rgb_values(), 3, 1), photometric="rgb",
                     planarconfig="separate", metadata=None)


def patch(path, offset, data):
    with open(path, "r+b") as file:
        file.seek(offset)
        file.write(data)


def replace_once(path, old, new):
    with open(path, "rb") as file:
        content = file.read()
    assert content.count(old) >= 1 and len(old) == len(new), (path, old)
    patch(path, content.index(old), new)


def write_contiguous(folder):
    """ImageJ's layout over 4 GiB: one IFD, the images one run after the first page's data."""
    path = os.path.join(folder, "contiguous.tif")
    tifffile.imwrite(path, hyperstack_values(), imagej=True, metadata={"axes": "TZCYX", "finterval": 30})
    with tifffile.TiffFile(path) as tiff:
        first = tiff.pages[0]
        offsets = [page.dataoffsets[0] for page in tiff.pages]
        next_pointer = first.offset + 2 + 12 * len(first.tags)
    assert offsets == [offsets[0] + 60 * i for i in range(len(offsets))], "tifffile wrote the data apart"
    patch(path, next_pointer, struct.pack("<I", 0))


def write_bad(folder):
    bad = os.path.join(folder, "bad")
    os.makedirs(bad)
    # A page whose strip points at the file's last bytes: the strip is cut short.
    path = os.path.join(bad, "strip_cut.tif")
    tifffile.imwrite(path, plain_values(), photometric="minisblack", metadata=None)
    size = os.path.getsize(path)
    with tifffile.TiffFile(path) as tiff:
        tag = tiff.pages[3].tags["StripOffsets"]
    patch(path, tag.valueoffset, struct.pack("<I", size - 10))
    # The whole file cut in two.
    path = os.path.join(bad, "truncated.tif")
    tifffile.imwrite(path, hyperstack_values(), imagej=True, metadata={"axes": "TZCYX"})
    os.truncate(path, os.path.getsize(path) // 2)
    # ImageJ's images= and OME's sizes that disagree with the pages.
    path = os.path.join(bad, "images_mismatch.tif")
    tifffile.imwrite(path, hyperstack_values(), imagej=True, metadata={"axes": "TZCYX"})
    replace_once(path, b"images=24", b"images=26")
    path = os.path.join(bad, "ome_sizes.ome.tif")
    tifffile.imwrite(path, ome_tzyx_values(), metadata={"axes": "TZYX"})
    replace_once(path, b'SizeT="3"', b'SizeT="9"')
    # A compression code no libtiff knows.
    path = os.path.join(bad, "compression.tif")
    tifffile.imwrite(path, plain_values(), photometric="minisblack", metadata=None)
    with tifffile.TiffFile(path) as tiff:
        tag = tiff.pages[0].tags["Compression"]
    patch(path, tag.valueoffset, struct.pack("<H", 40000))
    # Frames of 2D images: no z axis.
    tifffile.imwrite(os.path.join(bad, "no_z.tif"), np.zeros((3, 5, 6), np.uint16), imagej=True,
                     metadata={"axes": "TYX"})
    for name, kind in (("float16.tif", np.float16), ("complex.tif", np.complex64)):
        tifffile.imwrite(os.path.join(bad, name), np.ones((4, 5, 6), kind), photometric="minisblack", metadata=None)
    tifffile.imwrite(os.path.join(bad, "palette.tif"), np.ones((4, 5, 6), np.uint8), photometric="palette",
                     colormap=np.zeros((3, 256), np.uint16), metadata=None)
    tifffile.imwrite(os.path.join(bad, "one_bit.tif"), np.ones((4, 8, 8), bool), photometric="minisblack",
                     metadata=None)
    path = os.path.join(bad, "mixed_sizes.tif")
    tifffile.imwrite(path, np.ones((2, 5, 6), np.uint16), photometric="minisblack", metadata=None)
    tifffile.imwrite(path, np.ones((2, 7, 6), np.uint16), photometric="minisblack", metadata=None, append=True)


def write_nifti(path, volumes, spacing, step_seconds):
    """A NIfTI-1 file without sform or qform (so no orientation), in micrometres and seconds, of
    volumes indexed [t, z, y, x] (stored x fastest)."""
    t, z, y, x = volumes.shape
    header = bytearray(352)
    struct.pack_into("<i", header, 0, 348)
    struct.pack_into("<8h", header, 40, 4, x, y, z, t, 1, 1, 1)
    struct.pack_into("<hh", header, 70, 16, 32)  # float32
    struct.pack_into("<8f", header, 76, 1.0, spacing[0], spacing[1], spacing[2], step_seconds, 0, 0, 0)
    struct.pack_into("<f", header, 108, 352.0)
    header[123] = 3 | 8  # micrometres, seconds
    header[344:348] = b"n+1\0"
    with open(path, "wb") as file:
        file.write(bytes(header))
        file.write(volumes.astype("<f4").tobytes())


def time_lapse_values(frames=8, slices=24, size=112):
    """TZCYX uint16: a camera offset of 100 with noise; channel 0 the cells' nuclei (soft-edged
    ellipsoids), channel 1 the dimmer cytoplasm around them. Three cells: one in the image's top
    left drifting right, one in the bottom right drifting left, and the middle one dividing from
    frame 3 on, its daughters moving apart."""
    rng = np.random.default_rng(7)
    z, y, x = np.indices((slices, size, size)).astype(np.float64)
    z *= 2.5  # z steps of 0.5 um against 0.2 um pixels: distances in pixels of x
    data = np.zeros((frames, slices, 2, size, size))
    for t in range(frames):
        split = max(0, t - 2) * 5.0
        cells = [((24 + 4 * t, 22 + t, 28.0), 9.0), ((88 - 3 * t, 90, 30.0), 8.0)]
        if split:
            cells += [((56 - split * 0.8, 56 + split * 0.6, 30.0), 7.0),
                      ((56 + split * 0.8, 56 - split * 0.6, 30.0), 7.0)]
        else:
            cells += [((56, 56, 30.0), 10.0)]
        for (cx, cy, cz), radius in cells:
            # A nucleus longer in x than in y, so the picture shows which way is up.
            r = np.sqrt(((x - cx) / 1.3) ** 2 + (y - cy) ** 2 + (z - cz) ** 2)
            data[t, :, 0] += 3000 / (1 + np.exp((r - radius) / 1.2))
            data[t, :, 1] += 600 / (1 + np.exp((r - 1.8 * radius) / 3.0))
    data += 100 + rng.normal(0, 12, data.shape)
    return np.clip(data, 0, 65535).astype(np.uint16)


def write_time_lapse(path, ome):
    if ome:
        tifffile.imwrite(path, time_lapse_values(), metadata={
            "axes": "TZCYX", "PhysicalSizeX": 0.2, "PhysicalSizeY": 0.2, "PhysicalSizeZ": 0.5,
            "TimeIncrement": 30, "TimeIncrementUnit": "s"})
    else:
        tifffile.imwrite(path, time_lapse_values(), imagej=True, resolution=(1 / 0.2, 1 / 0.2),
                         metadata={"axes": "TZCYX", "spacing": 0.5, "unit": "um", "finterval": 30})


def main():
    if sys.argv[1] == "--time-lapse":
        write_time_lapse(sys.argv[2], "--ome" in sys.argv[3:])
        return
    folder = sys.argv[1]
    os.makedirs(folder, exist_ok=True)
    write_good(folder)
    write_contiguous(folder)
    write_bad(folder)
    # The hyperstack's channel 0 as NIfTI, turned as the TIFF reader turns it (rows and slices
    # reversed): both must show the same picture.
    channel0 = hyperstack_values()[:, :, 0].astype(np.float32)
    write_nifti(os.path.join(folder, "hyperstack_c0.nii"), channel0[:, ::-1, ::-1, :], (0.2, 0.2, 0.5), 30.0)


if __name__ == "__main__":
    main()
