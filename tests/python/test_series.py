"""tstyles.Series from numpy arrays, xarray DataArrays and files: no OpenGL needed."""

import ast
import gc
import pathlib

import numpy as np
import pytest
import xarray as xr

import tstyles
from conftest import run_cli


def normalised(values, low, high):
    """The density the C++ model stores: (v - low) / (high - low) in double, then float32."""
    return np.clip((np.asarray(values, dtype=np.float64) - low) / (high - low), 0.0, 1.0).astype(np.float32)


def test_a_4d_array_is_a_series_of_its_time_steps():
    data = np.arange(2 * 3 * 4 * 5, dtype=np.float32).reshape(2, 3, 4, 5)
    series = tstyles.Series(data, spacing=(0.5, 1.0, 2.0), times=[10.0, 20.0], name="ramp")
    assert len(series) == 2 and series.name == "ramp" and series.source_format == "numpy array"
    assert list(series.times) == [10.0, 20.0]
    assert series.value_range == (0.0, 119.0)
    step = series.step(1)
    assert step["dims"] == (5, 4, 3) and step["spacing"] == (0.5, 1.0, 2.0) and step["grid"] == "rectilinear"
    assert step["raw_range"] == (60.0, 119.0)
    for index in range(2):
        assert np.array_equal(series.density(index), normalised(data[index], 0.0, 119.0))


def test_nan_is_missing_and_left_out_of_the_range():
    data = np.full((2, 2, 2, 3), 4.0, dtype=np.float64)
    data[1] = 8.0
    data[0, 0, 0, 0] = np.nan
    data[1, 1, 1, 2] = 100.0
    data[1, 1, 1, 1] = np.nan
    series = tstyles.Series(data)
    assert series.value_range == (4.0, 100.0)
    density = series.density(0)
    assert np.isnan(density[0, 0, 0]) and np.count_nonzero(np.isnan(density)) == 1
    assert series.density(1)[0, 0, 0] == np.float32(4.0 / 96.0)


def test_a_list_of_arrays_has_its_own_shapes_spacings_placements_and_masks():
    first = np.arange(4 * 5 * 6, dtype=np.uint8).reshape(4, 5, 6)
    second = np.full((3, 3, 3), 300, dtype=np.uint16)
    second[0, 0, 0] = 0
    mask = (first > 50).astype(np.uint8)
    series = tstyles.Series([first, second], spacing=[(1, 1, 1), (0.5, 0.25, 0.5)],
                            origin=[(0, 0, 0), (2.0, 0.0, -1.0)], rotation=[None, ((0, 0, 1), 90.0)],
                            times=[0.0, 1.5], masks=[mask, None], value_range=(0, 255))
    assert series.value_range == (0.0, 255.0)
    assert series.step(0)["dims"] == (6, 5, 4) and series.step(1)["dims"] == (3, 3, 3)
    assert series.step(1)["spacing"] == (0.5, 0.25, 0.5) and series.step(1)["origin"] == (2.0, 0.0, -1.0)
    axis, angle = series.step(1)["rotation"]
    assert np.allclose(axis, (0, 0, 1)) and angle == pytest.approx(90.0)
    assert np.array_equal(series.density(1), normalised(second, 0, 255))  # 300 clamps to 1
    assert np.array_equal(series.mask(0), mask) and series.mask(1) is None


def test_coordinates_place_the_grid_unevenly_and_reverse_decreasing_axes():
    values = np.random.default_rng(7).random((3, 4, 5)).astype(np.float32)
    series = tstyles.Series(values[np.newaxis], coordinates={"x": np.linspace(10, 14, 5), "y": [5, 4, 3, 2],
                                                             "z": [0.0, 10.0, 30.0]})
    step = series.step(0)
    assert step["positions"] == {"z": [0.0, 10.0, 30.0]}
    assert step["origin"] == (10.0, 2.0, 0.0) and step["spacing"][:2] == (1.0, 1.0)
    low, high = float(values.min()), float(values.max())
    assert np.array_equal(series.density(0), normalised(values[:, ::-1, :], low, high))


def test_datetime64_stamps_count_from_the_unix_epoch_or_in_given_units():
    stamps = np.array(["2009-07-01T00:00", "2009-07-01T06:00", "2009-07-02T00:00"], dtype="datetime64[ns]")
    data = np.random.default_rng(1).random((3, 2, 2, 2))
    series = tstyles.Series(data, times=stamps)
    assert series.time_units == "seconds since 1970-01-01 00:00:00" and series.calendar == "proleptic_gregorian"
    assert np.array_equal(np.diff(series.times), [21600.0, 64800.0])
    assert np.array_equal(series.dates, stamps.astype("datetime64[us]"))
    hourly = tstyles.Series(data, times=stamps, time_units="hours since 2009-07-01")
    assert list(hourly.times) == [0.0, 6.0, 24.0]


def test_density_views_share_the_series_memory_and_keep_it_alive():
    series = tstyles.Series(np.random.default_rng(2).random((2, 8, 8, 8)))
    first = series.density(0)
    # A view, not a copy: a second view starts at the same address, and neither can be written.
    address = first.__array_interface__["data"][0]
    assert series.density(0).__array_interface__["data"][0] == address
    assert address != series.density(1).__array_interface__["data"][0]
    assert not first.flags.writeable and not first.flags.owndata
    expected = first.copy()
    del series
    gc.collect()
    assert np.array_equal(first, expected)


@pytest.mark.parametrize("make, message", [
    (lambda: tstyles.Series(np.zeros((3, 4))),
     "tstyles.Series: data: expected a 4D array (t, z, y, x) or a list of 3D arrays (z, y, x), got shape (3, 4)"),
    (lambda: tstyles.Series([np.zeros((3, 3))]),
     "tstyles.Series: data[0]: expected a 3D array (z, y, x), got shape (3, 3)"),
    (lambda: tstyles.Series(np.zeros((2, 3, 3, 3)), times=[0.0]),
     "tstyles.Series: times: expected 2 time stamps (one per time-step), got shape (1,)"),
    (lambda: tstyles.Series(np.arange(16.0).reshape(2, 2, 2, 2), times=[1.0, 0.0]),
     "tstyles.Series: times[1]: times must be strictly increasing: 0 follows 1"),
    (lambda: tstyles.Series(np.arange(16.0).reshape(2, 2, 2, 2), value_range=(np.nan, 1.0)),
     "tstyles.Series: value_range: expected finite [low, high] with low less than high, found [nan, 1]"),
    (lambda: tstyles.Series(np.full((2, 2, 2, 2), np.nan)),
     "tstyles.Series: every value of the chosen time-steps is missing: there is nothing to show"),
    (lambda: tstyles.Series(np.where(np.arange(16).reshape(2, 2, 2, 2) == 1, np.inf, 0.0)),
     "tstyles.Series: time-step 0 holds Inf at voxel (x, y, z) = (1, 0, 0): only NaN (or a declared fill value) "
     "marks missing data"),
    (lambda: tstyles.Series(np.zeros((1, 1, 3, 3))),
     "tstyles.Series: data[0]: shape (1, 3, 3): a grid needs two samples along each axis to span a box"),
    (lambda: tstyles.Series(np.zeros((1, 2, 2, 2), dtype=np.int64)),
     "tstyles.Series: data[0]: dtype int64 is not supported (uint8, uint16, int8, int16, int32, float32, "
     "float64): convert it with .astype(numpy.float32)"),
    (lambda: tstyles.Series(np.arange(8.0).reshape(1, 2, 2, 2), masks=[np.ones((2, 2, 3), np.uint8)]),
     "tstyles.Series: masks[0]: shape (2, 2, 3) differs from the values' (2, 2, 2)"),
    (lambda: tstyles.Series(np.arange(8.0).reshape(1, 2, 2, 2), spacing=(1, 0, 1)),
     "tstyles.Series: spacing: must be positive, found 0"),
])
def test_bad_arrays_raise_value_error_naming_the_argument(make, message):
    with pytest.raises(ValueError) as error:
        make()
    assert str(error.value) == message


def cli_message(executable, *arguments):
    code, stderr = run_cli(executable, *arguments)
    assert code == 2, stderr
    assert stderr.startswith("tstyles: ")
    return stderr[len("tstyles: "):].strip()


def test_open_errors_are_the_command_line_messages(realistic_datasets, tstyles_executable):
    ocean = realistic_datasets / "ocean-anomalies.nc"
    for options, arguments in [({"var": "nope"}, ["--var", "nope"]), ({"steps": slice(5, None)}, ["--steps", "5:"]),
                               ({"value_range": (2.0, 1.0)}, ["--range", "2.0:1.0"]),
                               ({"level": -1}, ["--level", "-1"]), ({"precision": 12}, ["--precision", "12"])]:
        with pytest.raises(ValueError) as error:
            tstyles.open(ocean, **options)
        assert str(error.value) == cli_message(tstyles_executable, "info", ocean, *arguments)
    with pytest.raises(ValueError) as error:
        tstyles.open(realistic_datasets / "missing.nc")
    assert str(error.value) == cli_message(tstyles_executable, "info", realistic_datasets / "missing.nc")


def test_open_takes_the_reader_options_of_the_table(realistic_datasets):
    """open()'s keywords are the reader options' table's (tstyles.reader_options()); another is a TypeError."""
    table = tstyles.reader_options()
    keywords = [line["keyword"] for line in table]
    assert {"var", "steps", "value_range", "level", "channel", "series", "max_memory", "gamma"} <= set(keywords)
    level = next(line for line in table if line["keyword"] == "level")
    assert (level["option"], level["kind"], level["bounds"]) == ("--level", "whole-number", "a whole number 0 or more")
    with pytest.raises(TypeError) as error:
        tstyles.open(realistic_datasets / "ocean-anomalies.nc", levels=1)
    assert "unexpected keyword argument 'levels'" in str(error.value) and "level" in str(error.value)
    first_two = tstyles.open(realistic_datasets / "ocean-anomalies.nc", steps=range(0, 2), index_axes=False)
    assert len(first_two) == 2


def assert_same_series(actual, expected):
    """The same series whatever it was read from: times, units, axes, grids, placements, densities."""
    assert len(actual) == len(expected)
    assert np.array_equal(actual.times, expected.times)
    assert (actual.time_units, actual.calendar) == (expected.time_units, expected.calendar)
    assert actual.time_labels == expected.time_labels
    assert actual.value_range == expected.value_range and actual.value_unit == expected.value_unit
    assert actual.axes == expected.axes
    for index in range(len(expected)):
        assert actual.step(index) == expected.step(index)
        assert np.array_equal(actual.density(index), expected.density(index), equal_nan=True)


def test_an_xarray_cf_ocean_on_a_noleap_calendar_equals_the_netcdf_reader(realistic_datasets):
    ocean = realistic_datasets / "ocean-anomalies.nc"
    with xr.open_dataset(ocean) as dataset:
        from_xarray = tstyles.from_xarray(dataset["thetao"])
    from_file = tstyles.open(ocean)
    assert from_xarray.source_format == "xarray DataArray" and from_file.source_format.startswith("NetCDF")
    assert from_file.step(0)["positions"]["z"], "the ocean's depth levels are uneven"
    assert from_file.calendar == "noleap"
    assert from_file.axes[2]["direction"] == "up"  # depth, positive down, turned
    assert np.isnan(from_file.density(0)).any(), "the land is missing"
    assert_same_series(from_xarray, from_file)


def test_an_xarray_array_with_datetime64_time_and_uneven_depth_equals_the_file_it_writes(tmp_path):
    rng = np.random.default_rng(3)
    values = rng.random((3, 4, 5, 6)).astype(np.float32) * 20.0
    values[:, :, 0, 0] = np.nan  # land
    depth = [0.0, 5.0, 20.0, 60.0]
    array = xr.DataArray(values, name="thetao", dims=("time", "depth", "lat", "lon"), coords={
        "time": np.array(["2000-01-01", "2000-01-16T12:00", "2000-02-01"], dtype="datetime64[ns]"),
        "depth": ("depth", depth, {"units": "m", "positive": "down", "standard_name": "depth"}),
        "lat": ("lat", np.linspace(40.0, 36.0, 5), {"units": "degrees_north"}),
        "lon": ("lon", np.linspace(-20.0, -15.0, 6), {"units": "degrees_east"}),
    }, attrs={"units": "degC"})
    file = tmp_path / "ocean.nc"
    array.to_dataset().to_netcdf(file)
    with xr.open_dataset(file) as dataset:
        assert dataset["time"].dtype.kind == "M"
        from_xarray = tstyles.from_xarray(dataset["thetao"])
    from_file = tstyles.open(file)
    assert from_file.step(0)["positions"] == {"z": [0.0, 40.0, 55.0, 60.0]}
    assert_same_series(from_xarray, from_file)
    assert np.array_equal(from_xarray.dates, array["time"].values.astype("datetime64[us]"))
    in_memory = tstyles.from_xarray(array)  # no file encoding: seconds since 1970
    assert np.array_equal(in_memory.dates, from_file.dates)
    assert np.array_equal(in_memory.density(2), from_file.density(2), equal_nan=True)


def test_xarray_arrays_of_the_wrong_rank_say_so():
    with pytest.raises(ValueError) as error:
        tstyles.from_xarray(xr.DataArray(np.zeros((2, 3)), name="t2m", dims=("lat", "lon")))
    assert str(error.value) == ("DataArray 't2m': t2m: has 2 dimensions (lat = 2, lon = 3): a volume series needs "
                                "three spatial dimensions and optionally time")


def test_the_package_modules_import_one_another_without_a_cycle():
    # Every import, lazy ones inside functions too, of one module of the package by another.
    package = pathlib.Path(tstyles.__file__).parent
    modules = {path.stem for path in package.glob("*.py")}
    imports = {}
    for module in modules:
        tree = ast.parse((package / f"{module}.py").read_text())
        named = set()
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.level == 1:
                named |= {node.module.split(".")[0]} if node.module else {alias.name for alias in node.names}
            elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("tstyles."):
                named.add(node.module.split(".")[1])
            elif isinstance(node, ast.Import):
                named |= {alias.name.split(".")[1] for alias in node.names if alias.name.startswith("tstyles.")}
        imports[module] = named & (modules - {"__init__"})

    def cycle_from(module, path):
        if module in path:
            return path[path.index(module):] + [module]
        return next((c for m in sorted(imports.get(module, ())) if (c := cycle_from(m, path + [module]))), None)

    # The scan sees the layering: Series wraps the xarray conversion, both build on _arrays.
    assert imports["series"] >= {"_arrays", "xarray_series"} and imports["xarray_series"] >= {"_arrays"}
    for module in sorted(modules):
        assert cycle_from(module, []) is None, " -> ".join(cycle_from(module, []))
