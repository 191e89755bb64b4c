"""Microscopy TIFFs written by tifffile, read back through tstyles.open: every value, the axes,
spacing, placement and times (tests/cli/write_tiff_samples.py writes the files; no OpenGL)."""

import pathlib
import sys

import numpy as np
import pytest

import tstyles

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "cli"))
import write_tiff_samples as samples  # noqa: E402


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    path = tmp_path_factory.mktemp("tiff")
    samples.write_good(path)
    samples.write_contiguous(path)
    return path


def assert_values(series, volumes):
    """Every step's density, in float32 precision, is (v - low) / (high - low) of the array written
    ([t][z, y, x], rows and slices in the file's order: the turn is in the placement)."""
    low, high = series.value_range
    assert (low, high) == (float(np.min(volumes)), float(np.max(volumes)))
    assert len(series) == len(volumes)
    for index, volume in enumerate(volumes):
        expected = ((np.asarray(volume, np.float64) - low) / (high - low)).astype(np.float32)
        assert np.array_equal(series.density(index), expected), "time-step %d" % index


def micrometre_axes():
    return [{"name": name, "unit": "um", "direction": "unknown"} for name in "xyz"]


def test_imagej_hyperstack_channels_spacing_and_frame_times(folder):
    values = samples.hyperstack_values()
    for channel in (0, 1):
        series = tstyles.open(folder / "hyperstack.tif", channel=channel, precision="32")
        assert series.source_format == "ImageJ hyperstack TIFF"
        assert_values(series, values[:, :, channel])
    assert list(series.times) == [0.0, 30.0, 60.0] and series.time_units == "seconds"
    assert series.axes == micrometre_axes()
    step = series.step(2)
    assert step["dims"] == (6, 5, 4) and step["spacing"] == pytest.approx((0.2, 0.2, 0.5))


def test_rows_run_down_and_slices_toward_the_viewer(folder):
    """A half turn about x: row 0 at the top (largest world y), slice 0 at the largest world z."""
    step = tstyles.open(folder / "hyperstack.tif").step(0)
    axis, angle = step["rotation"]
    assert np.allclose(np.abs(axis), (1, 0, 0)) and angle == pytest.approx(180.0)
    assert step["origin"] == pytest.approx((0.0, 4 * 0.2, 3 * 0.5))


def test_imagej_images_after_one_ifd_are_read_as_one_run(folder):
    series = tstyles.open(folder / "contiguous.tif", channel=1, precision="32")
    assert_values(series, samples.hyperstack_values()[:, :, 1])


def test_ome_tiff_physical_sizes_and_time_increment(folder):
    series = tstyles.open(folder / "tzyx.ome.tif", precision="32")
    assert series.source_format == "OME-TIFF"
    assert_values(series, samples.ome_tzyx_values())
    assert list(series.times) == [0.0, 2.0, 4.0] and series.time_units == "milliseconds"
    assert series.step(0)["spacing"] == pytest.approx((0.25, 0.25, 1.5))
    assert series.axes == micrometre_axes()


def test_ome_tiff_channels_as_planes_with_plane_delta_t_and_z_in_nanometres(folder):
    values = samples.ome_tzcyx_values()
    for channel in range(3):
        series = tstyles.open(folder / "tzcyx.ome.tif", channel=channel, precision="32")
        assert_values(series, values[:, :, channel])
    assert list(series.times) == [0.0, 1.5, 4.0] and series.time_units == "seconds"
    assert series.step(1)["spacing"] == pytest.approx((0.2, 0.2, 0.8))


def test_tiled_deflate_int8_with_partial_edge_tiles(folder):
    series = tstyles.open(folder / "tiled.ome.tif", precision="32")
    assert series.step(0)["dims"] == (40, 36, 3)
    assert_values(series, samples.tiled_values())


def test_plain_pages_one_volume_or_a_series_by_dims_and_axes(folder):
    pages = samples.plain_values()
    assert_values(tstyles.open(folder / "plain.tif", precision="32"), [pages])
    assert_values(tstyles.open(folder / "plain.tif", dims=(6, 5, 4), precision="32"), pages.reshape(3, 4, 5, 6))
    z_slowest = tstyles.open(folder / "plain.tif", dims=(6, 5, 4), axes="ZTYX", precision="32")
    assert_values(z_slowest, pages.reshape(4, 3, 5, 6).transpose(1, 0, 2, 3))
    assert list(z_slowest.times) == [0.0, 1.0, 2.0]


def test_folders_in_natural_name_order(folder):
    steps = tstyles.open(folder / "steps", precision="32")
    assert steps.source_format == "TIFF (3 files)"
    assert_values(steps, [samples.folder_step_values(step) for step in range(3)])
    slices = tstyles.open(folder / "slices", precision="32")
    assert_values(slices, [np.stack([samples.slice_values(z) for z in range(5)])])


def test_samples_per_pixel_are_channels_interleaved_or_planar(folder):
    values = samples.rgb_values()
    for name in ("rgb.tif", "rgb_planar.tif"):
        for channel in range(3):
            assert_values(tstyles.open(folder / name, channel=channel, precision="32"), [values[..., channel]])


def test_errors_name_the_file_and_the_field(folder):
    with pytest.raises(ValueError) as error:
        tstyles.open(folder / "hyperstack.tif", channel=2)
    assert str(error.value) == ("%s: --channel: 2 is out of range: the image has 2 channels (0 to 1)"
                                % (folder / "hyperstack.tif"))
