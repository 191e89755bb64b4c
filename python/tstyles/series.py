"""Series: time-varying volumes from numpy arrays and from every file the tstyles executable reads."""

import os

import numpy as np

from . import _native

_SOURCE = "tstyles.Series"
_UNIX_EPOCH = "seconds since 1970-01-01 00:00:00"


def _fail(source, field, problem):
    """The one shape of every input error: "source: field: problem", as the command line prints it."""
    raise ValueError(f"{source}: {field}: {problem}")


def _native_order(array):
    """numpy arrays in the machine's byte order are read where they lie; others need one converted copy."""
    return array if array.dtype.isnative else array.astype(array.dtype.newbyteorder("="))


def _time_steps(data, source):
    """The 3D (z, y, x) arrays of the time-steps: views into a 4D array, or the arrays of a list."""
    if isinstance(data, (list, tuple)):
        steps = [_native_order(np.asarray(step)) for step in data]
        for index, step in enumerate(steps):
            if step.ndim != 3:
                _fail(source, f"data[{index}]", f"expected a 3D array (z, y, x), got shape {step.shape}")
        return steps
    array = _native_order(np.asarray(data))
    if array.ndim != 4:
        _fail(source, "data", f"expected a 4D array (t, z, y, x) or a list of 3D arrays (z, y, x), got shape {array.shape}")
    return [array[index] for index in range(array.shape[0])]


def _per_step(value, count, is_single, name, source):
    """One value for every time-step, or a list of one per time-step."""
    if value is None or is_single(value):
        return [value] * count
    values = list(value)
    if len(values) != count:
        _fail(source, name, f"expected one for all time-steps or {count} (one per time-step), got {len(values)}")
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
            _fail(source, field, "expected {\"axis\": [x, y, z], \"angle_deg\": a}")
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
        _fail(source, "times", f"expected {count} time stamps (one per time-step), got shape {stamps.shape}")
    if stamps.dtype.kind == "M" or stamps.dtype == object:
        if not time_units:
            time_units, calendar = _UNIX_EPOCH, calendar or "proleptic_gregorian"
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


class Series:
    """A time-varying volume: time-steps, each on its own grid and placement (docs/python.md).

    Made from a 4D numpy array (t, z, y, x) or a list of 3D arrays (z, y, x), from an
    xarray.DataArray (Series.from_xarray) or from a file (tstyles.open). NaN marks a voxel without
    data. C-contiguous or strided arrays are read where they lie: the only copy is the series'
    own densities (raw values mapped to [0, 1] by the value range), as with every file reader.
    """

    def __init__(self, data, *, spacing=None, coordinates=None, origin=None, rotation=None, times=None,
                 masks=None, value_range=None, name="", value_unit="", time_units="", calendar="", axes=None,
                 precision=16):
        self._native = _native.build_series(_array_spec(
            data, spacing=spacing, coordinates=coordinates, origin=origin, rotation=rotation, times=times,
            masks=masks, value_range=value_range, name=name, value_unit=value_unit, time_units=time_units,
            calendar=calendar, axes=axes, precision=precision, source=_SOURCE, source_format="numpy array"))

    @classmethod
    def _wrap(cls, native):
        series = cls.__new__(cls)
        series._native = native
        return series

    @classmethod
    def from_xarray(cls, array, **options):
        """The series of an xarray.DataArray (see tstyles.from_xarray)."""
        from .xarray_series import from_xarray
        return from_xarray(array, **options)

    def __len__(self):
        return len(self._native)

    def __repr__(self):
        return (f"<tstyles.Series {self.name!r}: {len(self)} time-steps from {self.source_format}, "
                f"values {self.value_range[0]:g} .. {self.value_range[1]:g} {self.value_unit}>")

    name = property(lambda self: self._native.name)
    source = property(lambda self: self._native.source, doc="The file (or array) the series came from.")
    source_format = property(lambda self: self._native.source_format)
    time_units = property(lambda self: self._native.time_units, doc='CF units: "days since 1950-01-01 00:00:00".')
    calendar = property(lambda self: self._native.calendar)
    time_labels = property(lambda self: self._native.time_labels, doc="Times as info and legends show them.")
    value_range = property(lambda self: tuple(self._native.value_range), doc="Raw values mapped to density 0 and 1.")
    value_unit = property(lambda self: self._native.value_unit)
    precision = property(lambda self: self._native.precision, doc="Bits per density on the GPU: 8, 16 or 32.")
    axes = property(lambda self: self._native.axes, doc="World x, y, z: name, unit and direction.")

    @property
    def times(self):
        """The time stamps as numbers in time_units."""
        return np.array(self._native.times)

    @property
    def dates(self):
        """The time stamps as numpy datetime64 (standard and proleptic Gregorian calendars), else None."""
        if self.calendar not in ("standard", "proleptic_gregorian"):
            return None
        fields = _native.dates(self.time_units, self.calendar, list(self._native.times))
        if not fields:
            return None
        return np.array([np.datetime64(f"{y:04d}-{mo:02d}-{d:02d}T{h:02d}:{mi:02d}", "us") +
                         np.timedelta64(int(round(s * 1e6)), "us") for y, mo, d, h, mi, s in fields])

    def step(self, index):
        """Time-step `index`: time, grid kind, dims (x, y, z), spacing, uneven positions, origin, rotation."""
        return self._native.step(index)

    def density(self, index):
        """Time-step `index`'s densities in [0, 1] (NaN: missing), a read-only (z, y, x) view."""
        return self._native.density(index)

    def mask(self, index):
        """Time-step `index`'s mask, a read-only (z, y, x) uint8 view, or None."""
        return self._native.mask(index)

    def describe(self):
        """What `tstyles info` prints about the series."""
        return self._native.describe()


def _array_spec(data, *, spacing, coordinates, origin, rotation, times, masks, value_range, name, value_unit,
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
            _fail(source, "origin", "give the origin or coordinates, not both: coordinates place the first node")
        step_spacing = (1.0, 1.0, 1.0) if spacings[index] is None else spacings[index]
        steps.append({
            "values": values[index],
            "mask": None if mask_list[index] is None else _native_order(np.asarray(mask_list[index])),
            "time": stamps[index],
            "axes": [_axis_nodes(step_spacing, coordinate_sets[index], axis, coordinate_attributes, axis_names)
                     for axis in range(3)],
            "origin": tuple(float(c) for c in (origins[index] if origins[index] is not None else (0, 0, 0))),
            "rotation": _rotation(rotations[index], source, "rotation"),
        })
    if value_range is not None:
        value_range = tuple(float(v) for v in value_range)
        if len(value_range) != 2:
            _fail(source, "value_range", "expected [low, high]")
    return {
        "source": source, "format": source_format, "name": name, "value_unit": value_unit,
        "axes": None if axes is None else [dict(axis) for axis in axes],
        "time_units": time_units, "calendar": calendar, "steps": steps,
        "missing_values": [float(v) for v in missing_values], "scale": float(scale), "offset": float(offset),
        "value_range": value_range, "precision": str(precision),
    }


def _steps_text(steps):
    if steps is None or isinstance(steps, str):
        return steps
    if isinstance(steps, (slice, range)):
        if any(v is not None and v < 0 for v in (steps.start, steps.stop, steps.step)):
            raise ValueError("--steps: negative indices are not supported; give first:end:stride")
        start = steps.start or 0
        stop = "" if steps.stop is None else steps.stop
        return f"{start}:{stop}:{steps.step or 1}"
    raise ValueError("--steps: expected \"first:end:stride\", a slice or a range")


def open(path, *, var=None, steps=None, time_dim=None, index_axes=False, value_range=None, resample=None,
         dims=None, precision=None, max_memory=None, fit=None, solution=(), block=0, gamma=1.4, channel=None,
         series=None, axes=None, level=None):
    """Opens any dataset the executable reads (manifest, NetCDF, NIfTI, NRRD, Plot3D, Isabel files; TIFF,
    OME-Zarr, DICOM, VTK XML).

    The options are those of `tstyles render`/`info` (docs/readers.md): var=--var, steps=--steps
    ("0:48:5" or slice(0, 48, 5)), value_range=--range (low, high), resample=--resample (nx, ny, nz),
    and so on; problems raise ValueError with the message the command line prints.
    """
    paths = [os.fspath(p) for p in path] if isinstance(path, (list, tuple)) else [os.fspath(path)]
    options = {
        "var": var, "time_dim": time_dim, "index_axes": bool(index_axes), "steps": _steps_text(steps),
        "range": None if value_range is None else f"{float(value_range[0])!r}:{float(value_range[1])!r}",
        "resample": None if resample is None else "x".join(str(int(n)) for n in resample),
        "dims": None if dims is None else "x".join(str(int(n)) for n in dims),
        "precision": None if precision is None else str(precision),
        "max_memory": None if max_memory is None else str(max_memory), "fit": fit,
        "solution": [os.fspath(p) for p in solution], "block": int(block), "gamma": float(gamma),
        "channel": None if channel is None else int(channel), "series": None if series is None else str(series),
        "axes": axes, "level": None if level is None else int(level),
    }
    return Series._wrap(_native.open_series(paths, options))
