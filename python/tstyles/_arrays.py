"""Arrays to series: the spec `_native.build_series` takes, made from numpy arrays and per-step
arguments, and the input errors it raises. Shared by tstyles.Series (series.py) and the xarray
conversion (xarray_series.py); it imports neither."""

import numpy as np

from . import _native

UNIX_EPOCH = "seconds since 1970-01-01 00:00:00"


def fail(source, field, problem):
    """The one shape of every input error: "source: field: problem", as the command line prints it."""
    raise ValueError(f"{source}: {field}: {problem}")


def native_order(array):
    """numpy arrays in the machine's byte order are read where they lie; others need one converted copy."""
    return array if array.dtype.isnative else array.astype(array.dtype.newbyteorder("="))


def _time_steps(data, source):
    """The 3D (z, y, x) arrays of the time-steps: views into a 4D array, or the arrays of a list."""
    if isinstance(data, (list, tuple)):
        steps = [native_order(np.asarray(step)) for step in data]
        for index, step in enumerate(steps):
            if step.ndim != 3:
                fail(source, f"data[{index}]", f"expected a 3D array (z, y, x), got shape {step.shape}")
        return steps
    array = native_order(np.asarray(data))
    if array.ndim != 4:
        fail(source, "data", f"expected a 4D array (t, z, y, x) or a list of 3D arrays (z, y, x), got shape {array.shape}")
    return [array[index] for index in range(array.shape[0])]


def _per_step(value, count, is_single, name, source):
    """One value for every time-step, or a list of one per time-step."""
    if value is None or is_single(value):
        return [value] * count
    values = list(value)
    if len(values) != count:
        fail(source, name, f"expected one for all time-steps or {count} (one per time-step), got {len(values)}")
    return values


def _is_vector(value):
    return np.ndim(value) == 1 and np.size(value) == 3


def _is_rotation(value):
    if isinstance(value, dict):
        return True
    return isinstance(value, (list, tuple)) and len(value) == 2 and _is_vector(value[0]) and np.ndim(value[1]) == 0


def _rotation(value, source, field):
    """(axis, angle_deg) or {"axis": [...], "angle_deg": a}, as a manifest spells it."""
    if value is None:
        return None
    if isinstance(value, dict):
        if set(value) != {"axis", "angle_deg"}:
            fail(source, field, "expected {\"axis\": [x, y, z], \"angle_deg\": a}")
        value = (value["axis"], value["angle_deg"])
    axis, angle = value
    return (tuple(float(c) for c in axis), float(angle))


def _date_fields(stamp):
    """(year, month, day, hour, minute, second) of a datetime, a numpy datetime64 or a cftime date."""
    if isinstance(stamp, np.datetime64):
        stamp = stamp.astype("datetime64[us]").item()
    return (stamp.year, stamp.month, stamp.day, stamp.hour, stamp.minute, stamp.second + stamp.microsecond * 1e-6)


def time_values(stamps, units, calendar, source, field="times"):
    """Dates (datetime64, datetime or cftime) as values on a CF time axis ("days since 1950-01-01")."""
    return _native.time_values(units, calendar, [_date_fields(stamp) for stamp in stamps], source, field)


def _step_times(times, count, time_units, calendar, source):
    """The time stamps as numbers, and the CF units and calendar they count in."""
    if times is None:
        return [float(index) for index in range(count)], time_units, calendar
    stamps = np.asarray(times)
    if stamps.ndim != 1 or len(stamps) != count:
        fail(source, "times", f"expected {count} time stamps (one per time-step), got shape {stamps.shape}")
    if stamps.dtype.kind == "M" or stamps.dtype == object:
        if not time_units:
            time_units, calendar = UNIX_EPOCH, calendar or "proleptic_gregorian"
        return time_values(stamps, time_units, calendar, source), time_units, calendar
    return [float(value) for value in stamps], time_units, calendar


def _axis_nodes(spacing, coordinates, axis, attributes, names):
    """Where the nodes of one axis lie: `spacing` apart, or at the given coordinates."""
    name = "xyz"[axis]
    given = None if coordinates is None else coordinates.get(name)
    return {
        "name": names[axis] if names and names[axis] else name,
        "spacing": float(spacing[axis]),
        "coordinates": None if given is None else [float(value) for value in np.asarray(given).ravel()],
        "attributes": attributes[axis] if attributes else {},
    }


def array_spec(data, *, spacing, coordinates, origin, rotation, times, masks, value_range, name, value_unit,
               time_units, calendar, axes, precision, source, source_format, coordinate_attributes=None,
               axis_names=None, missing_values=(), scale=1.0, offset=0.0):
    """What _native.build_series takes: every per-step argument spread over the time-steps."""
    values = _time_steps(data, source)
    count = len(values)
    spacings = _per_step(spacing, count, _is_vector, "spacing", source)
    coordinate_sets = _per_step(coordinates, count, lambda c: isinstance(c, dict), "coordinates", source)
    origins = _per_step(origin, count, _is_vector, "origin", source)
    rotations = _per_step(rotation, count, _is_rotation, "rotation", source)
    if masks is not None and not isinstance(masks, (list, tuple)):
        masks = list(np.asarray(masks))
    mask_list = _per_step(masks, count, lambda m: False, "masks", source)
    stamps, time_units, calendar = _step_times(times, count, time_units, calendar, source)
    steps = []
    for index in range(count):
        if origins[index] is not None and coordinate_sets[index] is not None:
            fail(source, "origin", "give the origin or coordinates, not both: coordinates place the first node")
        step_spacing = (1.0, 1.0, 1.0) if spacings[index] is None else spacings[index]
        steps.append({
            "values": values[index],
            "mask": None if mask_list[index] is None else native_order(np.asarray(mask_list[index])),
            "time": stamps[index],
            "axes": [_axis_nodes(step_spacing, coordinate_sets[index], axis, coordinate_attributes, axis_names)
                     for axis in range(3)],
            "origin": tuple(float(c) for c in (origins[index] if origins[index] is not None else (0, 0, 0))),
            "rotation": _rotation(rotations[index], source, "rotation"),
        })
    if value_range is not None:
        value_range = tuple(float(v) for v in value_range)
        if len(value_range) != 2:
            fail(source, "value_range", "expected [low, high]")
    return {
        "source": source, "format": source_format, "name": name, "value_unit": value_unit,
        "axes": None if axes is None else [dict(axis) for axis in axes],
        "time_units": time_units, "calendar": calendar, "steps": steps,
        "missing_values": [float(v) for v in missing_values], "scale": float(scale), "offset": float(offset),
        "value_range": value_range, "precision": str(precision),
    }
