#!/usr/bin/env python3
"""Writes the seed corpus of tests/fuzz/corpus/ (small, valid or nearly valid inputs of each parser).

Usage: write_seed_corpus.py SAMPLES DATA
  SAMPLES: a folder written by build/tests/write_reader_samples (NetCDF, NRRD, NIfTI, Isabel, PNG)
  DATA:    the bundled data folder after a build (data/: scenes and generated styles)
Seeds are named seed-*; inputs that found a bug are named after the bug (crash-*, oom-*, ...) and
are kept by hand. Rerunning replaces the seeds only.
"""
import gzip
import json
import pathlib
import shutil
import struct
import subprocess
import sys

CORPUS = pathlib.Path(__file__).resolve().parent / "corpus"


def put(target, name, data):
    folder = CORPUS / target
    folder.mkdir(parents=True, exist_ok=True)
    (folder / ("seed-" + name)).write_bytes(data if isinstance(data, bytes) else data.encode())


def step(time, grid, values="values.raw", mask=None, **extra):
    entry = {"time": time, "grid": grid, "values": {"file": values, "type": "float32"}}
    if mask:
        entry["mask"] = {"file": mask}
    entry.update(extra)
    return entry


def manifest(steps, **extra):
    document = {"format": "tstyles-series", "version": 1, "name": "fuzz", "value_range": [0.0, 1.0],
                "time_steps": steps}
    document.update(extra)
    return json.dumps(document, indent=1)


def manifest_seeds():
    # fuzz_manifest.cpp puts values.raw (4x4x4 float32), mask.raw (4x4x4 bytes), values8.raw (2x2x2
    # float32) and coords.f32 (2x2x2 nodes) beside the manifest.
    box = {"type": "rectilinear", "dims": [4, 4, 4], "spacing": [0.5, 0.5, 1.0]}
    placement = {"origin": [0, 0, 0], "rotation": {"axis": [0, 0, 1], "angle_deg": 30}}
    put("manifest", "rectilinear", manifest([step(0.0, box), step(1.0, box, placement=placement)]))
    put("manifest", "mask-missing", manifest([step(0.0, box, mask="mask.raw")], missing_value=0.0))
    uneven = {"type": "rectilinear", "dims": [4, 4, 4], "spacing": [0.5, 0.5, None],
              "positions": {"z": [0.0, 0.1, 0.3, 0.7]}}
    put("manifest", "uneven", manifest([step(0.0, uneven)], time_units="hours since 2000-01-01"))
    beam = {"type": "beam", "dims": [4, 4, 4], "azimuth_deg": [-30, 30], "elevation_deg": [-20, 20],
            "range": [2, 120]}
    put("manifest", "beam", manifest([step(0.0, beam, mask="mask.raw")]))
    structured = {"type": "structured", "dims": [2, 2, 2], "coordinates": {"file": "coords.f32"}}
    put("manifest", "structured", manifest([step(0.0, structured, values="values8.raw")]))


def scene_seeds(data):
    for name in ["figure1-styled-focus-step3", "figure4-max-density-change", "figure6-centre-index-tstf",
                 "warped-box-styled", "figure5-focus-step5"]:
        put("scene", name, (data / "scenes" / (name + ".json")).read_bytes())


def plot3d_grid(little=True):
    order = "<" if little else ">"
    dims = (2, 2, 2)
    grid = struct.pack(order + "3i", *dims)
    nodes = [(i, j, k) for k in range(2) for j in range(2) for i in range(2)]
    for axis in range(3):
        grid += b"".join(struct.pack(order + "f", float(node[axis])) for node in nodes)
    solution = struct.pack(order + "3i", *dims) + struct.pack(order + "4f", 0.5, 0.0, 1e6, 0.0)
    solution += b"".join(struct.pack(order + "f", value) for value in [1.0 + n / 10 for n in range(8)] + [0.1] * 24 + [10.0] * 8)
    function = struct.pack(order + "4i", *dims, 2) + b"".join(struct.pack(order + "f", v) for v in range(16))
    return grid, solution, function


def plot3d_seeds():
    for little in (True, False):
        grid, solution, function = plot3d_grid(little)
        prefix = struct.pack("<H", len(grid))
        put("plot3d", ("little" if little else "big") + "-q", prefix + b"\x00" + grid + solution)
        put("plot3d", ("little" if little else "big") + "-function", prefix + b"\x01" + grid + function)


def png_seed(data):
    tiny = CORPUS / "style_image" / "seed-tiny.png"
    tiny.parent.mkdir(parents=True, exist_ok=True)
    subprocess.run(["oiiotool", "--pattern", "checker:width=2:height=2", "8x8", "4", "-d", "uint8", "-o", str(tiny)],
                   check=True)
    subprocess.run(["oiiotool", "--pattern", "constant:color=0.5", "4x4", "1", "-d", "uint8", "-o",
                    str(CORPUS / "style_image" / "seed-grey.png")], check=True)


def zarr_seed(version, attributes, metadata, chunk):
    """fuzz_zarr's input: '2' or '3', then the group attributes, the level-0 array metadata and one chunk."""
    return version.encode() + json.dumps(attributes).encode() + b"\0" + json.dumps(metadata).encode() + b"\0" + chunk


def zarr_seeds():
    import numcodecs
    import numpy as np

    space = [{"name": n, "type": "space", "unit": "micrometer"} for n in "zyx"]
    timed = [{"name": "t", "type": "time", "unit": "second"}, {"name": "c", "type": "channel"}] + space
    scale = [{"type": "scale", "scale": [2.0, 0.5, 0.5]}, {"type": "translation", "translation": [1.0, 0.0, 0.0]}]
    zyx = {"multiscales": [{"version": "0.4", "axes": space, "datasets": [{"path": "0", "coordinateTransformations": scale}]}]}
    tczyx = {"multiscales": [{"version": "0.4", "axes": timed, "datasets": [
        {"path": "0", "coordinateTransformations": [{"type": "scale", "scale": [5.0, 1.0, 2.0, 0.5, 0.5]}]}]}]}
    values = (np.arange(2 * 3 * 4 * 4) % 251).astype("<u2")

    def zarray(shape, dtype, compressor, order="C", fill=0):
        return {"zarr_format": 2, "shape": shape, "chunks": shape, "dtype": dtype, "compressor": compressor,
                "fill_value": fill, "order": order, "filters": None, "dimension_separator": "."}

    put("zarr", "v2-zlib-tczyx", zarr_seed("2", tczyx, zarray([2, 1, 3, 4, 4], "<u2", {"id": "zlib", "level": 5}),
                                           numcodecs.Zlib(5).encode(values.tobytes())))
    put("zarr", "v2-blosc-big-endian", zarr_seed("2", zyx, zarray([3, 4, 4], ">u2", {"id": "blosc", "cname": "lz4"}),
                                                 numcodecs.Blosc("lz4").encode(values[:48].astype(">u2").tobytes())))
    put("zarr", "v2-lz4-fortran", zarr_seed("2", zyx, zarray([3, 4, 4], "|u1", {"id": "lz4"}, order="F"),
                                            numcodecs.LZ4().encode(values[:48].astype("u1").tobytes())))
    put("zarr", "v2-zstd-float-nan", zarr_seed("2", zyx, zarray([3, 4, 4], "<f4", {"id": "zstd"}, fill="NaN"),
                                               numcodecs.Zstd().encode(values[:48].astype("<f4").tobytes())))
    put("zarr", "v2-raw", zarr_seed("2", zyx, zarray([3, 4, 4], "<i2", None), values[:48].astype("<i2").tobytes()))
    group = {"zarr_format": 3, "node_type": "group",
             "attributes": {"ome": {"version": "0.5", "multiscales": [
                 {"axes": space, "datasets": [{"path": "0", "coordinateTransformations": scale}]}]}}}
    raw = values[:48].tobytes()
    gzipped = gzip.compress(raw, mtime=0)
    array = {"zarr_format": 3, "node_type": "array", "shape": [3, 4, 4], "data_type": "uint16",
             "chunk_grid": {"name": "regular", "configuration": {"chunk_shape": [3, 4, 4]}},
             "chunk_key_encoding": {"name": "default"}, "fill_value": 0,
             "codecs": [{"name": "bytes", "configuration": {"endian": "little"}}, {"name": "gzip"}, {"name": "crc32c"}]}
    checksum = struct.pack("<I", crc32c(gzipped))
    put("zarr", "v3-gzip-crc32c", zarr_seed("3", group, array, gzipped + checksum))
    sharded = dict(array, codecs=[{"name": "sharding_indexed", "configuration": {
        "chunk_shape": [3, 4, 4], "codecs": [{"name": "bytes", "configuration": {"endian": "little"}}, {"name": "gzip"}],
        "index_codecs": [{"name": "bytes", "configuration": {"endian": "little"}}, {"name": "crc32c"}]}}])
    index = struct.pack("<QQ", 0, len(gzipped))
    put("zarr", "v3-sharded", zarr_seed("3", group, sharded, gzipped + index + struct.pack("<I", crc32c(index))))


def crc32c(data):
    crc = 0xFFFFFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ (0x82F63B78 if crc & 1 else 0)
    return crc ^ 0xFFFFFFFF
def tiff_seeds():
    """An ImageJ hyperstack, an OME-TIFF (deflate), plain float pages and LZMA tiles, written with
    tifffile (python3-tifffile) as users' files are; each well under 16 KiB."""
    import numpy as np
    import tifffile
    folder = CORPUS / "tiff"
    folder.mkdir(parents=True, exist_ok=True)
    t, z, c, y, x = np.indices((2, 2, 2, 3, 5))
    tifffile.imwrite(folder / "seed-imagej.tif", (t * 50 + z * 20 + c * 7 + y * 3 + x).astype(np.uint8), imagej=True,
                     resolution=(5, 5), metadata={"axes": "TZCYX", "spacing": 0.5, "unit": "um", "finterval": 30})
    tifffile.imwrite(folder / "seed-ome.ome.tif", (np.arange(2 * 2 * 3 * 5, dtype=np.uint16) * 11).reshape(2, 2, 3, 5),
                     compression="zlib", metadata={"axes": "TZYX", "PhysicalSizeX": 0.2, "PhysicalSizeY": 0.2,
                                                   "PhysicalSizeZ": 0.5, "TimeIncrement": 2, "TimeIncrementUnit": "s"})
    tifffile.imwrite(folder / "seed-plain.tif", (np.arange(3 * 3 * 5, dtype=np.float32) * 0.5).reshape(3, 3, 5),
                     metadata=None)
    tifffile.imwrite(folder / "seed-tiled.tif", (np.arange(3 * 20 * 18, dtype=np.int16) - 300).reshape(3, 20, 18),
                     tile=(16, 16), compression="lzma", metadata=None)
    # Float data with NaN over "land" (missing data, not an error) and OME sizes in km and m.
    sea = (np.arange(2 * 2 * 4 * 5, dtype=np.float32) * 0.25).reshape(2, 2, 4, 5)
    sea[:, :, :, :2] = np.nan
    tifffile.imwrite(folder / "seed-nan-sea.ome.tif", sea,
                     metadata={"axes": "TZYX", "PhysicalSizeX": 2.0, "PhysicalSizeXUnit": "km",
                               "PhysicalSizeZ": 5.0, "PhysicalSizeZUnit": "m"})


def main():
    samples, data = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    for target in ["manifest", "scene", "nrrd", "netcdf", "netcdf_header", "nifti", "isabel", "plot3d", "style_image",
                   "zarr", "tiff"]:
        for seed in (CORPUS / target).glob("seed-*"):
            seed.unlink()
    manifest_seeds()
    scene_seeds(data)
    for name in ["classic.nc", "offset64.nc", "nan.nc", "notime.nc"]:
        for target in ["netcdf", "netcdf_header"]:
            put(target, name, (samples / name).read_bytes())
    volume = (samples / "volume.nrrd").read_bytes()
    put("nrrd", "attached.nrrd", volume)
    put("nrrd", "gzip.nrrd", volume.replace(b"encoding: raw", b"encoding: gzip").split(b"\n\n")[0] + b"\n\n" +
        gzip.compress(volume.split(b"\n\n", 1)[1]))
    put("nrrd", "detached.nhdr", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 8 8 4\nencoding: raw\n"
                                 "spacings: 1 1 2\ndata file: volume.raw\n")
    put("nifti", "bold.nii", gzip.decompress((samples / "bold.nii.gz").read_bytes()))
    put("isabel", "QCLOUDf01.bin", (samples / "QCLOUDf01.bin").read_bytes())
    put("isabel", "QCLOUDf01.bin.gz", gzip.compress((samples / "QCLOUDf01.bin").read_bytes()))
    plot3d_seeds()
    png_seed(data)
    put("style_image", "huge-header.png", (samples / "huge.png").read_bytes())
    zarr_seeds()
    tiff_seeds()


if __name__ == "__main__":
    main()
