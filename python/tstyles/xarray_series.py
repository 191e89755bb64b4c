"""xarray.DataArray to the spec of a series (_native.build_series; tstyles.from_xarray wraps the
result): dimensions and coordinates from the array, CF attributes read the way the NetCDF reader
reads them (the same C++ code: src/data/cf_conventions.cpp), time stamps as numpy datetime64,
cftime dates or numbers with CF units. xarray itself is not imported: the array is read through
its own attributes."""

import numpy as np

from . import _native
from ._arrays import UNIX_EPOCH, array_spec, fail, native_order, time_values

_CF_KEYS = ("units", "standard_name", "axis", "positive")


def _attributes(coordinate):
    return {key: str(coordinate.attrs[key]) for key in _CF_KEYS if key in coordinate.attrs}


def _dimension_list(array):
    return "(" + ", ".join(f"{name} = {size}" for name, size in zip(array.dims, array.shape)) + ")"


def _is_date(coordinate):
    return coordinate.dtype.kind == "M" or (coordinate.dtype == object and hasattr(coordinate.values.flat[0], "calendar"))


def _looks_like_time(array, dimension):
    if dimension not in array.coords:
        return _native.looks_like_time(dimension, None)
    coordinate = array.coords[dimension]
    return _is_date(coordinate) or _native.looks_like_time(dimension, _attributes(coordinate))


def _time_dimension(array, time_dim, source, name):
    if time_dim is not None:
        if time_dim not in array.dims:
            fail(source, "time_dim", f'variable {name} has no dimension "{time_dim}"')
        return time_dim
    return next((d for d in array.dims if _looks_like_time(array, d)), None)


def _times(array, time_dim, source):
    """The stamps as numbers, and their CF units and calendar (the file's, where xarray kept them)."""
    if time_dim is None:
        return None, "", ""
    if time_dim not in array.coords:
        return [float(i) for i in range(array.sizes[time_dim])], "", ""
    coordinate = array.coords[time_dim]
    units = coordinate.encoding.get("units", coordinate.attrs.get("units", ""))
    calendar = coordinate.encoding.get("calendar", coordinate.attrs.get("calendar", ""))
    if coordinate.dtype.kind == "M":
        if not units:
            units, calendar = UNIX_EPOCH, "proleptic_gregorian"
        return time_values(coordinate.values, units, calendar, source, time_dim), units, calendar
    if _is_date(coordinate):
        calendar = calendar or coordinate.values.flat[0].calendar
        units = units or "days since 1970-01-01 00:00:00"
        return time_values(coordinate.values, units, calendar, source, time_dim), units, calendar
    return [float(v) for v in coordinate.values], units, calendar


def _packing(array):
    """CF packing still in the attributes (xarray opened with mask_and_scale=False): honoured as the
    NetCDF reader honours it. Decoded arrays carry it in .encoding and hold NaN instead."""
    markers = []
    for key in ("_FillValue", "missing_value"):
        if key in array.attrs:
            markers.extend(float(v) for v in np.atleast_1d(array.attrs[key]))
    return markers, float(array.attrs.get("scale_factor", 1.0)), float(array.attrs.get("add_offset", 0.0))


def data_array_spec(array, *, time_dim, value_range, precision):
    """What _native.build_series takes for an xarray.DataArray (tstyles.from_xarray says how it is read)."""
    name = str(array.name) if array.name is not None else "data"
    source = f"DataArray '{name}'"
    dimension = _time_dimension(array, time_dim, source, name)
    rank = array.ndim
    if rank not in (3, 4):
        fail(source, name, f"has {rank} dimensions {_dimension_list(array)}: a volume series needs three spatial "
                           "dimensions and optionally time")
    if rank == 4 and dimension is None:
        fail(source, name, f"cannot find the time dimension among {_dimension_list(array)}: no dimension has a "
                           "datetime coordinate, axis = \"T\" or units \"... since ...\", and none is named like "
                           "time; name it with time_dim")
    if rank == 3 and dimension is not None:
        fail(source, name, f"has only two spatial dimensions besides time {_dimension_list(array)}: a volume "
                           "needs three")
    spatial = [d for d in array.dims if d != dimension]
    ordered = array.transpose(*([dimension] if dimension else []), *spatial)
    values = native_order(np.asarray(ordered.values))  # a view where xarray holds numpy data
    data = values if dimension else values[np.newaxis]
    z, y, x = spatial
    coordinates = {axis: array.coords[d].values for axis, d in zip("xyz", (x, y, z)) if d in array.coords}
    attributes = [_attributes(array.coords[d]) if d in array.coords else {} for d in (x, y, z)]
    times, time_units, calendar = _times(array, dimension, source)
    markers, scale, offset = _packing(array)
    return array_spec(
        data, spacing=None, coordinates=coordinates or None, origin=None, rotation=None, times=times, masks=None,
        value_range=value_range, name=name, value_unit=str(array.attrs.get("units", "")), time_units=time_units,
        calendar=calendar, axes=None, precision=precision, source=source, source_format="xarray DataArray",
        coordinate_attributes=attributes, axis_names=[x, y, z], missing_values=markers, scale=scale, offset=offset)
