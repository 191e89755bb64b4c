"""Series: time-varying volumes from numpy arrays, from xarray DataArrays and from every file the tstyles
executable reads."""

import os

import numpy as np

from . import _native, xarray_series
from ._arrays import array_spec

_SOURCE = "tstyles.Series"


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
        self._native = _native.build_series(array_spec(
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

    def at(self, x, y, z):
        """The values at place (x, y, z) over time, in the file's coordinates as `describe()` lists
        them (a depth or pressure level as the file counts it: 500 for 500 hPa), each time-step
        sampled in its own grid (docs/probe.md): as an xarray DataArray over "time" when xarray is there, else a tuple of
        numpy arrays (times, values). Values are in the data's own unit (the density mapping
        undone); NaN where a time-step's grid does not reach the place or has no data there."""
        values = np.array(self._native.values_at(float(x), float(y), float(z)))
        try:
            import xarray
        except ImportError:
            return self.times, values
        dates = self.dates
        return xarray.DataArray(values, dims=["time"], coords={"time": dates if dates is not None else self.times},
                                name=self.name, attrs={"units": self.value_unit, "place": (x, y, z)})


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


def _option_texts(line, value):
    """The command-line texts of one reader option's value (None: not given)."""
    kind, option = line["kind"], line["option"]
    if value is None:
        return None
    if kind == "flag":
        return ["true"] if bool(value) else None
    if kind == "steps":
        return [_steps_text(value)]
    if kind == "value-range" and not isinstance(value, str):
        low, high = value
        return [f"{float(low)!r}:{float(high)!r}"]
    if kind == "dims" and not isinstance(value, str):
        return ["x".join(str(int(n)) for n in value)]
    if kind == "files":
        paths = [value] if isinstance(value, (str, os.PathLike)) else list(value)
        return [os.fspath(p) for p in paths] or None
    if kind == "whole-number" and isinstance(value, bool):
        raise ValueError(f"{option}: must be {line['bounds']}; got {value!r}")
    return [str(value)]


def _reader_options():
    return {line["keyword"]: line for line in _native.reader_options()}


def open(path, **options):
    """Opens any dataset the executable reads: a manifest, or a file, folder or store of any format of
    docs/readers.md.

    The keyword options are the reader options of `tstyles render`/`info`, from the same table
    (docs/readers.md, and tstyles.reader_options()): var=--var, steps=--steps ("0:48:5", slice(0, 48, 5)
    or range(...)), value_range=--range ((low, high) or "low:high"), resample=--resample ((nx, ny, nz)),
    dims=, channel=, level=, series=, axes=, precision=, max_memory=, fit=, solution= (paths), block=,
    gamma=, time_dim=, index_axes=True; problems raise ValueError with the message the command line
    prints, an unknown keyword TypeError.
    """
    table = _reader_options()
    unknown = sorted(set(options) - set(table))
    if unknown:
        raise TypeError(f"open() got an unexpected keyword argument {unknown[0]!r}; "
                        f"the reader options are: {', '.join(table)}")
    paths = [os.fspath(p) for p in path] if isinstance(path, (list, tuple)) else [os.fspath(path)]
    texts = {}
    for keyword, value in options.items():
        given = _option_texts(table[keyword], value)
        if given is not None:
            texts[keyword] = given
    return Series._wrap(_native.open_series(paths, texts))


def reader_options():
    """The reader options open() takes, one dict each: keyword, option (the command line's spelling),
    kind, value, bounds, default and help."""
    return [dict(line) for line in _native.reader_options()]


def from_xarray(array, *, time_dim=None, value_range=None, precision=16):
    """The series of an xarray.DataArray of three spatial dimensions and optionally time.

    The time dimension is found as the NetCDF reader finds it (a datetime coordinate, axis = "T",
    units "... since ...", or a name like time) unless time_dim names it. The other dimensions are
    z, y, x in order (x fastest); their coordinates place the grid (uneven ones too), with
    depths and pressures turned so that +z is up. NaN (xarray's decoded fill values) is missing.
    """
    spec = xarray_series.data_array_spec(array, time_dim=time_dim, value_range=value_range, precision=precision)
    return Series._wrap(_native.build_series(spec))
