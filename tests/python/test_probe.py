"""Series.at: the values of a place over time, on series whose value is a known linear function
(tests/cli/write_probe_samples.py), as the command line's `probe` gives them."""

import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "cli"))
from write_probe_samples import TIMES, f, write_all  # noqa: E402

import tstyles  # noqa: E402

# The densities are float32: value ranges of about 35, so about 2e-6 apart (the CLI test's bound).
TOLERANCE = 4e-6


@pytest.fixture(scope="module")
def samples(tmp_path_factory):
    folder = tmp_path_factory.mktemp("probe")
    write_all(str(folder))
    return folder


@pytest.mark.parametrize("grid, place", [("even", (2.5, 3.3, 3.7)), ("uneven", (2.25, 4.1, 4.2)),
                                         ("structured", (3.6, 4.5, 3.35))])
def test_at_gives_the_function_between_nodes(samples, grid, place):
    at = tstyles.open(str(samples / grid / "series.json")).at(*place)
    expected = [f(*place, t) for t in TIMES]
    values = at.values if hasattr(at, "values") else at[1]
    assert np.allclose(values, expected, rtol=0.0, atol=TOLERANCE)


def test_at_is_a_data_array_over_time_with_nan_outside(samples):
    pytest.importorskip("xarray")
    series = tstyles.open(str(samples / "even" / "series.json"))
    at = series.at(3.0, 4.0, 3.5)
    assert at.dims == ("time",)
    assert list(at.coords["time"].values) == list(TIMES)
    assert np.allclose(at.values, [f(3.0, 4.0, 3.5, t) for t in TIMES], rtol=0.0, atol=TOLERANCE)
    outside = series.at(100.0, 4.0, 3.5)
    assert np.isnan(outside.values).all()


def test_at_takes_a_pressure_level_as_the_file_counts_it(tmp_path):
    """A CF forecast written by netCDF4-python, levels 500 to 1000 hPa counting down: at(lon, lat,
    700) is netCDF4's column at that node, exactly as float32, masked values NaN."""
    netCDF4 = pytest.importorskip("netCDF4")
    from write_probe_forecast import write

    path = str(tmp_path / "forecast.nc")
    write(path)
    series = tstyles.open(path)
    at = series.at(-95.0, 38.0, 700.0)
    values = at.values if hasattr(at, "values") else at[1]
    with netCDF4.Dataset(path) as root:
        i = list(root["lon"][:]).index(-95.0)
        j = list(root["lat"][:]).index(38.0)
        k = list(root["level"][:]).index(700.0)
        column = root["air"][:, k, j, i]
    expected = np.ma.filled(column.astype(np.float64), np.nan)
    np.testing.assert_array_equal(np.float32(values), np.float32(expected))
    below = series.at(-95.0, 38.0, -700.0)  # the world's sign: outside the file's levels
    assert np.isnan(below.values if hasattr(below, "values") else below[1]).all()
