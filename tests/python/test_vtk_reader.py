"""tstyles.open of ParaView time series (.pvd, .series, .vti, .vts, a parallel .pvtr, legacy .vtk)
that VTK's own writers made (python3-vtk9): times, frames and values come back as written."""

import os
import sys

import numpy as np
import pytest

pytest.importorskip("vtk")
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "cli"))
from write_vtk_samples import known, write_all  # noqa: E402

import tstyles  # noqa: E402


def normalised(values, low, high):
    """The density the C++ model stores: (v - low) / (high - low) in double, then float32."""
    return np.clip((np.asarray(values, dtype=np.float64) - low) / (high - low), 0.0, 1.0).astype(np.float32)


@pytest.fixture(scope="module")
def samples(tmp_path_factory):
    folder = tmp_path_factory.mktemp("vtk")
    write_all(str(folder))
    return folder


@pytest.mark.parametrize("listing", ["plume.pvd", "plume.vti.series"])
def test_a_listed_series_keeps_its_times_origins_and_values(samples, listing):
    series = tstyles.open(str(samples / listing))
    assert series.source_format == "VTK XML ImageData"
    assert list(series.times) == [0.5, 1.5, 4.0]
    # temperature = 0.5 i + 2 j + 10 k + 100 t on 5 x 4 x 3 points: 0 at step 0 to 228 at step 2.
    assert series.value_range == (0.0, 228.0)
    for index in range(3):
        step = series.step(index)
        assert step["dims"] == (5, 4, 3) and step["spacing"] == (0.5, 1.0, 2.0)
        assert step["origin"] == (0.25 * index, 1.0, 2.0)
        assert np.array_equal(series.density(index), normalised(known("temperature", index), 0.0, 228.0))


def test_var_picks_the_array_and_a_vector_is_its_magnitude(samples):
    pressure = tstyles.open(str(samples / "binary_lz4.vti"), var="pressure")
    low, high = pressure.value_range
    assert (low, high) == (-14.0, 12.0)
    assert np.array_equal(pressure.density(0), normalised(known("pressure", 0), low, high))
    velocity = tstyles.open(str(samples / "appended_base64_lzma.vti"), var="velocity")
    low, high = velocity.value_range
    assert np.allclose(velocity.density(0), normalised(known("velocity-magnitude", 0), low, high), atol=1e-6)


def test_a_structured_grid_keeps_its_points(samples):
    series = tstyles.open(str(samples / "grid.vts"))
    step = series.step(0)
    assert step["grid"] == "structured" and step["dims"] == (5, 4, 3)
    assert np.array_equal(series.density(0), normalised(known("temperature", 0), 0.0, 28.0))


def test_an_unknown_array_is_an_input_error_listing_the_arrays(samples):
    with pytest.raises(Exception, match="no point array named 'nope'; the point arrays are: pressure, label"):
        tstyles.open(str(samples / "ascii.vti"), var="nope")


def test_legacy_files_in_a_pvd_keep_their_times_origins_and_values(samples):
    series = tstyles.open(str(samples / "legacy.pvd"))
    assert series.source_format == "VTK legacy STRUCTURED_POINTS"
    assert list(series.times) == [0.5, 1.5, 4.0]
    assert series.value_range == (0.0, 228.0)
    for index in range(3):
        step = series.step(index)
        assert step["dims"] == (5, 4, 3) and step["origin"] == (0.25 * index, 1.0, 2.0)
        assert np.array_equal(series.density(index), normalised(known("temperature", index), 0.0, 228.0))


def test_a_parallel_rectilinear_grid_is_assembled_from_its_piece_files(samples):
    series = tstyles.open(str(samples / "parallel" / "depth.pvtr"))
    assert series.source_format == "VTK XML RectilinearGrid"
    assert series.step(0)["dims"] == (5, 4, 3)
    assert np.array_equal(series.density(0), normalised(known("temperature", 0), 0.0, 28.0))
