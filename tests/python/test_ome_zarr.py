"""The OME-Zarr reader against stores written at test time (tests/data/ome_zarr_stores.py): every
codec and layout reads back the values written, with the axes, spacing, origin and time stamps of
the multiscales metadata, the channel and level asked for, and the notes `tstyles info` prints."""

import os
import subprocess
import sys

import numpy as np
import pytest

import tstyles

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "data"))
import ome_zarr_stores as stores  # noqa: E402

# Densities are values / RANGE in 32-bit floats: every value (below 4000) comes back within 1e-3.
RANGE = 4000.0


def values_read(series, step):
    return np.asarray(series.density(step), dtype=np.float64) * RANGE


@pytest.fixture(scope="module")
def store_folder(tmp_path_factory):
    folder = tmp_path_factory.mktemp("stores")
    written = {}

    def write(kind):
        if kind not in written:
            path = folder / f"{kind}.zarr"
            written[kind] = (path, stores.STORES[kind](str(path)))
        return written[kind]

    return write


@pytest.mark.parametrize("kind", sorted(stores.KNOWN_STORES))
def test_values_axes_and_times_come_back(store_folder, kind):
    path, written = store_folder(kind)
    series = tstyles.open(path, value_range=(0, RANGE), precision=32)
    assert series.source_format == ("OME-Zarr 0.5" if kind.startswith("v3") else "OME-Zarr 0.4")
    assert len(series) == 3
    # t = 60 s + 30 s * index (the level's translation and scale of t).
    assert list(series.times) == [60.0, 90.0, 120.0]
    assert series.time_units.startswith("second")
    assert [(a["name"], a["unit"], a["direction"]) for a in series.axes] == [
        ("x", "um", "unknown"), ("y", "um", "unknown"), ("z", "um", "unknown")]
    for step in range(3):
        info = series.step(step)
        assert info["dims"] == (7, 6, 5)
        assert info["spacing"] == pytest.approx((0.25, 0.5, 2.0))
        # Turned 180 degrees about x (row 0 at the top): the origin (x, y, z) = (2.5, 1.5, -3) becomes (2.5, -1.5, 3).
        assert info["origin"] == pytest.approx((2.5, -1.5, 3.0))
        axis, angle = info["rotation"]
        assert axis == pytest.approx((1.0, 0.0, 0.0)) and angle == pytest.approx(180.0)
        np.testing.assert_allclose(values_read(series, step), written[step, 0], atol=1e-3)


def test_missing_chunk_is_the_fill_value(store_folder):
    path, written = store_folder("v2_zstd")
    assert not (path / "0" / "0.0.0.0.0").exists()
    series = tstyles.open(path, value_range=(0, RANGE), precision=32)
    assert np.all(values_read(series, 0)[0:3, 0:4, 0:4] == 0)
    assert written[0, 0, 0:3, 0:4, 0:4].sum() == 0 and written[0, 0].sum() > 0


@pytest.mark.parametrize("kind", ["v2_blosc_lz4", "v3_sharded"])
def test_channel_option_picks_the_channel(store_folder, kind):
    path, written = store_folder(kind)
    series = tstyles.open(path, value_range=(0, RANGE), precision=32, channel=1)
    for step in range(3):
        np.testing.assert_allclose(values_read(series, step), written[step, 1], atol=1e-3)


@pytest.mark.parametrize("kind", ["v2_gzip", "v3_blosc"])
def test_level_option_reads_the_coarser_level(store_folder, kind):
    path, written = store_folder(kind)
    series = tstyles.open(path, value_range=(0, RANGE), precision=32, level=1)
    info = series.step(2)
    assert info["dims"] == (4, 3, 5)
    assert info["spacing"] == pytest.approx((0.5, 1.0, 2.0))
    # The level's translation is half a fine step further along y and x: (2.625, 1.75, -3) turned.
    assert info["origin"] == pytest.approx((2.625, -1.75, 3.0))
    np.testing.assert_allclose(values_read(series, 2), stores.coarser(written)[2, 0], atol=1e-3)


def test_finest_level_that_fits_the_memory_is_taken_and_noted(store_folder, tstyles_executable):
    path, written = store_folder("v2_lz4")
    # Level 0: 3 steps of 7 x 6 x 5 voxels at 4 + 4 bytes = 5040 bytes; level 1: 3 x 4 x 3 x 5 x 8 = 1440.
    series = tstyles.open(path, value_range=(0, RANGE), precision=32, max_memory=3000)
    assert series.step(0)["dims"] == (4, 3, 5)
    np.testing.assert_allclose(values_read(series, 1), stores.coarser(written)[1, 0], atol=1e-3)
    info = subprocess.run([tstyles_executable, "info", str(path), "--max-memory", "3000", "--precision", "32"],
                          capture_output=True, text=True, check=True).stdout
    assert "Read: level 1 of 2 (4 x 3 x 5): level 0 (7 x 6 x 5) needs" in info


def test_info_says_how_it_was_read(store_folder, tstyles_executable):
    path, _ = store_folder("v3_sharded")
    info = subprocess.run([tstyles_executable, "info", str(path), "--channel", "1"],
                          capture_output=True, text=True, check=True).stdout
    assert "Read: OME-Zarr 0.5 on Zarr v3, axes t, c, z, y, x, image \"cells\"" in info
    assert "Read: level 0 of 2, the finest (--level picks another)" in info
    assert "Read: channel 1 (\"membrane\") of 2 (--channel)" in info
    assert "Read: array 0: uint16, codecs gzip, sharded" in info


def test_store_named_by_its_metadata_file(store_folder):
    for kind, name in (("v3_gzip", "zarr.json"), ("v2_none", ".zattrs")):
        path, written = store_folder(kind)
        series = tstyles.open(path / name, value_range=(0, RANGE), precision=32)
        np.testing.assert_allclose(values_read(series, 2), written[2, 0], atol=1e-3)
