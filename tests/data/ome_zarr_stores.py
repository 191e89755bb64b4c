"""Small OME-Zarr stores with known values, written at test time for the OME-Zarr reader's tests.

Zarr v2 + OME-NGFF 0.4 through zarr-python 2 (Debian's python3-zarr) with the .zattrs written by
hand; Zarr v3 + OME-NGFF 0.5 written by hand from the specs (zarr.json, chunk keys, codecs, shards),
since zarr-python 2 writes no v3. Run as a script: `ome_zarr_stores.py KIND FOLDER` writes one store.
"""

import gzip
import json
import os
import shutil
import struct
import sys

import numpy as np

# t, c, z, y, x: small, with chunks that do not divide the shape (edge chunks are partial).
SHAPE = (3, 2, 5, 6, 7)
CHUNKS = (1, 1, 3, 4, 4)
SCALE = [30.0, 1.0, 2.0, 0.5, 0.25]  # seconds, -, micrometres z, y, x
TRANSLATION = [60.0, 0.0, -3.0, 1.5, 2.5]
CHANNEL_LABELS = ["nuclei", "membrane"]
# The chunk (t=0, c=0, z 0-2, y 0-3, x 0-3) holds only the fill value, and its file is removed.
EMPTY_BLOCK = (0, 0, slice(0, 3), slice(0, 4), slice(0, 4))


def known_values(dtype="<u2"):
    """Every value tells where it is: 1 + x + 8 y + 64 z + 400 c + 1000 t (0 in the empty block)."""
    t, c, z, y, x = np.indices(SHAPE)
    values = (1 + x + 8 * y + 64 * z + 400 * c + 1000 * t).astype(dtype)
    values[EMPTY_BLOCK] = 0
    return values


def coarser(values):
    """Level 1: every second y and x."""
    return np.ascontiguousarray(values[..., ::2, ::2])


def level_transforms(level):
    scale = list(SCALE)
    translation = list(TRANSLATION)
    if level == 1:
        # The coarser samples sit between two finer ones: half a fine step further along y and x.
        for axis in (3, 4):
            translation[axis] += SCALE[axis] / 2
            scale[axis] *= 2
    return [{"type": "scale", "scale": scale}, {"type": "translation", "translation": translation}]


def multiscales(version, levels=2):
    axes = [{"name": "t", "type": "time", "unit": "second"}, {"name": "c", "type": "channel"}]
    axes += [{"name": name, "type": "space", "unit": "micrometer"} for name in ("z", "y", "x")]
    datasets = [{"path": str(level), "coordinateTransformations": level_transforms(level)} for level in range(levels)]
    image = {"name": "cells", "axes": axes, "datasets": datasets}
    if version == "0.4":
        image["version"] = version
    return [image]


def omero():
    return {"channels": [{"label": label} for label in CHANNEL_LABELS]}


# --- Zarr v2 + OME 0.4 (zarr-python 2) -----------------------------------------------------------

def write_v2(folder, compressor, dtype="<u2", separator=".", order="C", remove_empty_chunk=True):
    """A two-level store; the empty block's chunk file is removed (read back as the fill value)."""
    import zarr

    if os.path.exists(folder):
        shutil.rmtree(folder)
    os.makedirs(folder)
    with open(os.path.join(folder, ".zgroup"), "w") as out:
        json.dump({"zarr_format": 2}, out)
    with open(os.path.join(folder, ".zattrs"), "w") as out:
        json.dump({"multiscales": multiscales("0.4"), "omero": omero()}, out, indent=1)
    values = known_values(dtype)
    for level, data in enumerate((values, coarser(values))):
        array = zarr.open_array(os.path.join(folder, str(level)), mode="w", shape=data.shape, chunks=CHUNKS,
                                dtype=dtype, compressor=compressor, fill_value=0, order=order,
                                dimension_separator=separator)
        array[...] = data
    if remove_empty_chunk:
        os.remove(os.path.join(folder, "0", separator.join(["0"] * 5)))
    return values


def v2_compressors():
    import numcodecs

    return {
        "blosc_lz4": numcodecs.Blosc(cname="lz4", clevel=5, shuffle=numcodecs.Blosc.SHUFFLE),
        "blosc_zstd": numcodecs.Blosc(cname="zstd", clevel=3, shuffle=numcodecs.Blosc.BITSHUFFLE),
        "zlib": numcodecs.Zlib(level=6),
        "gzip": numcodecs.GZip(level=6),
        "zstd": numcodecs.Zstd(level=3),
        "lz4": numcodecs.LZ4(),
        "none": None,
    }


# --- Zarr v3 + OME 0.5 (by hand, from the specs) -------------------------------------------------

def crc32c(data):
    """CRC-32C (Castagnoli, reflected), as the crc32c codec appends it."""
    crc = 0xFFFFFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ (0x82F63B78 if crc & 1 else 0)
    return crc ^ 0xFFFFFFFF


def padded_chunk(data, index, chunks, fill=0):
    """The chunk at `index` (in chunks), padded with the fill value to the whole chunk shape."""
    region = tuple(slice(i * n, min((i + 1) * n, size)) for i, n, size in zip(index, chunks, data.shape))
    chunk = np.full(chunks, fill, dtype=data.dtype)
    part = data[region]
    chunk[tuple(slice(0, n) for n in part.shape)] = part
    return chunk


def encode_bytes(chunk, compression):
    raw = chunk.astype(chunk.dtype.newbyteorder("<")).tobytes()
    if compression == "gzip":
        return gzip.compress(raw, compresslevel=5, mtime=0)
    if compression == "blosc":
        import numcodecs

        return numcodecs.Blosc(cname="lz4", clevel=5, shuffle=numcodecs.Blosc.SHUFFLE).encode(raw)
    return raw


def codec_list(compression):
    codecs = [{"name": "bytes", "configuration": {"endian": "little"}}]
    if compression == "gzip":
        codecs.append({"name": "gzip", "configuration": {"level": 5}})
    elif compression == "blosc":
        codecs.append({"name": "blosc", "configuration": {"cname": "lz4", "clevel": 5, "shuffle": "shuffle",
                                                          "typesize": 2, "blocksize": 0}})
    return codecs


def chunk_indices(shape, chunks):
    return np.ndindex(*[(size + n - 1) // n for size, n in zip(shape, chunks)])


def write_v3_array(folder, data, compression, shard=None):
    """One array: chunks of CHUNKS, or shards of `shard` holding CHUNKS-sized inner chunks."""
    os.makedirs(folder)
    metadata = {"zarr_format": 3, "node_type": "array", "shape": list(data.shape), "data_type": "uint16",
                "chunk_grid": {"name": "regular", "configuration": {"chunk_shape": list(shard or CHUNKS)}},
                "chunk_key_encoding": {"name": "default", "configuration": {"separator": "/"}},
                "fill_value": 0, "codecs": codec_list(compression), "attributes": {},
                "dimension_names": ["t", "c", "z", "y", "x"]}
    if shard:
        metadata["codecs"] = [{"name": "sharding_indexed", "configuration": {
            "chunk_shape": list(CHUNKS), "codecs": codec_list(compression),
            "index_codecs": [{"name": "bytes", "configuration": {"endian": "little"}}, {"name": "crc32c"}],
            "index_location": "end"}}]
    with open(os.path.join(folder, "zarr.json"), "w") as out:
        json.dump(metadata, out, indent=1)
    outer = shard or CHUNKS
    for index in chunk_indices(data.shape, outer):
        path = os.path.join(folder, "c", *map(str, index))
        os.makedirs(os.path.dirname(path), exist_ok=True)
        block = padded_chunk(data, index, outer)
        with open(path, "wb") as out:
            out.write(encode_shard(block, compression) if shard else encode_bytes(block, compression))


def encode_shard(block, compression):
    """Inner chunks in C order, an all-fill inner chunk left out, the index (and its CRC) at the end."""
    body = b""
    index = b""
    for inner in chunk_indices(block.shape, CHUNKS):
        chunk = padded_chunk(block, inner, CHUNKS)
        if not chunk.any():
            index += struct.pack("<QQ", 2**64 - 1, 2**64 - 1)
            continue
        encoded = encode_bytes(chunk, compression)
        index += struct.pack("<QQ", len(body), len(encoded))
        body += encoded
    return body + index + struct.pack("<I", crc32c(index))


def write_v3(folder, compression, shard=None):
    if os.path.exists(folder):
        shutil.rmtree(folder)
    os.makedirs(folder)
    group = {"zarr_format": 3, "node_type": "group",
             "attributes": {"ome": {"version": "0.5", "multiscales": multiscales("0.5"), "omero": omero()}}}
    with open(os.path.join(folder, "zarr.json"), "w") as out:
        json.dump(group, out, indent=1)
    values = known_values("<u2")
    for level, data in enumerate((values, coarser(values))):
        write_v3_array(os.path.join(folder, str(level)), data, compression, shard)
    if not shard:  # the empty block's chunk is not stored
        os.remove(os.path.join(folder, "0", "c", "0", "0", "0", "0", "0"))
    return values


# --- A realistic time-lapse, for trying the reader as a user (docs/readers/ome-zarr.md) -------------

def write_timelapse(folder):
    """Cells drifting and growing over 8 time points (2 min apart): nuclei (channel 0) and membranes
    (channel 1), 8 x 2 x 32 x 96 x 128 uint16, 0.4 um pixels and 1 um planes, camera noise, Blosc-zstd
    chunks of one plane stack, two levels. The cells sit in the top half of the image (small y), the
    largest at the left: a picture shows at once whether it is upside down or mirrored."""
    import numcodecs
    import zarr

    if os.path.exists(folder):
        shutil.rmtree(folder)
    os.makedirs(folder)
    shape = (8, 2, 32, 96, 128)
    rng = np.random.default_rng(7)
    z, y, x = np.indices(shape[2:]).astype(np.float32)
    # (x, y, z) centre at t = 0 in pixels, drift per time point, radius at t = 0 in pixels, growth.
    cells = [((28, 24, 16), (3.0, 0.5), 14, 0.8), ((70, 30, 14), (2.0, -0.5), 10, 0.6),
             ((100, 22, 18), (1.5, 1.0), 7, 0.5)]
    values = np.empty(shape, dtype="<u2")
    for t in range(shape[0]):
        nuclei = np.zeros(shape[2:], np.float32)
        membranes = np.zeros(shape[2:], np.float32)
        for (cx, cy, cz), (vx, vy), radius, growth in cells:
            r = radius + growth * t
            # Planes are 2.5 times as far apart as pixels: the cell is round in micrometres.
            d = np.sqrt((x - cx - vx * t) ** 2 + (y - cy - vy * t) ** 2 + ((z - cz) * 2.5) ** 2) / r
            nuclei += 3000 * np.exp(-(d / 0.45) ** 2)
            membranes += 2000 * np.exp(-((d - 1.0) / 0.08) ** 2)
        for c, signal in enumerate((nuclei, membranes)):
            values[t, c] = np.clip(100 + signal + rng.normal(0, 20, shape[2:]), 0, 65535).astype("<u2")
    pyramid = (values, np.ascontiguousarray(values[..., ::2, ::2]))
    datasets = []
    for level, data in enumerate(pyramid):
        array = zarr.open_array(os.path.join(folder, str(level)), mode="w", shape=data.shape,
                                chunks=(1, 1, 32, 64, 64), dtype="<u2", fill_value=0,
                                compressor=numcodecs.Blosc(cname="zstd", clevel=5, shuffle=numcodecs.Blosc.BITSHUFFLE),
                                dimension_separator="/")
        array[...] = data
        step = 0.4 * 2**level
        datasets.append({"path": str(level), "coordinateTransformations": [
            {"type": "scale", "scale": [120.0, 1.0, 1.0, step, step]}]})
    axes = [{"name": "t", "type": "time", "unit": "second"}, {"name": "c", "type": "channel"}]
    axes += [{"name": n, "type": "space", "unit": "micrometer"} for n in "zyx"]
    with open(os.path.join(folder, ".zgroup"), "w") as out:
        json.dump({"zarr_format": 2}, out)
    with open(os.path.join(folder, ".zattrs"), "w") as out:
        json.dump({"multiscales": [{"version": "0.4", "name": "drifting cells", "axes": axes, "datasets": datasets}],
                   "omero": {"channels": [{"label": "H2B-GFP"}, {"label": "membrane-mCherry"}]}}, out, indent=1)


# Shards of 2 x 2 inner chunks along y and x: the empty block is a missing inner chunk.
SHARD = (1, 1, 3, 8, 8)

# The stores holding known_values() (the time-lapse is for looking at).
KNOWN_STORES = {
    **{f"v2_{name}": (lambda folder, c=name: write_v2(folder, v2_compressors()[c])) for name in
       ("blosc_lz4", "blosc_zstd", "zlib", "gzip", "zstd", "lz4", "none")},
    "v2_big_endian": lambda folder: write_v2(folder, v2_compressors()["zlib"], dtype=">u2"),
    "v2_nested": lambda folder: write_v2(folder, v2_compressors()["blosc_lz4"], separator="/"),
    "v2_fortran": lambda folder: write_v2(folder, v2_compressors()["zstd"], order="F"),
    "v2_float": lambda folder: write_v2(folder, v2_compressors()["gzip"], dtype="<f4"),
    "v3_gzip": lambda folder: write_v3(folder, "gzip"),
    "v3_blosc": lambda folder: write_v3(folder, "blosc"),
    "v3_sharded": lambda folder: write_v3(folder, "gzip", shard=SHARD),
}
STORES = {**KNOWN_STORES, "timelapse": write_timelapse}

if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in STORES:
        sys.exit("usage: ome_zarr_stores.py KIND FOLDER; KIND: " + ", ".join(STORES))
    STORES[sys.argv[1]](sys.argv[2])
