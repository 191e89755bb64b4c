#!/usr/bin/env python3
"""A CF forecast written by netCDF4-python, the library a scientist's NetCDF files come from, and the
check of `tstyles probe --json` at one of its grid nodes against what netCDF4 reads there.

    write_probe_forecast.py write FILE
    write_probe_forecast.py check FILE PROBE_JSON LON LAT LEVEL

The file: air temperature (K, float32, with noise) on 4 forecast hours x 5 pressure levels (1000 to
500 hPa, stored top-down as many models write them: 500 first) x 6 latitudes x 8 longitudes,
"hours since 2026-11-28 00:00:00", a _FillValue over a patch of high ground at 1000 hPa (missing)
and one masked value at hour 12. `check` compares the probe's times, time units and calendar with
the file's, its place with the node's coordinates as the file has them (the level in hPa, not
negated), and its values with netCDF4's at the node, exactly as float32 (a missing value is null),
and exits 1 on a difference.
"""
import json
import sys

import netCDF4
import numpy as np

LONS = np.linspace(-100.0, -93.0, 8)
LATS = np.linspace(35.0, 40.0, 6)
LEVELS = np.array([500.0, 600.0, 700.0, 850.0, 1000.0])  # hPa, top-down
HOURS = np.array([0.0, 6.0, 12.0, 18.0])
FILL = np.float32(-9999.0)


def write(path):
    rng = np.random.default_rng(55)
    with netCDF4.Dataset(path, "w", format="NETCDF4") as root:
        root.Conventions = "CF-1.8"
        root.title = "probe forecast (netCDF4-python)"
        for name, size in (("time", None), ("level", LEVELS.size), ("lat", LATS.size), ("lon", LONS.size)):
            root.createDimension(name, size)
        coordinates = (
            ("time", "f8", HOURS, {"units": "hours since 2026-11-28 00:00:00", "calendar": "standard",
                                   "standard_name": "time"}),
            ("level", "f4", LEVELS, {"units": "hPa", "standard_name": "air_pressure", "positive": "down"}),
            ("lat", "f4", LATS, {"units": "degrees_north", "standard_name": "latitude"}),
            ("lon", "f4", LONS, {"units": "degrees_east", "standard_name": "longitude"}),
        )
        for name, kind, values, attributes in coordinates:
            variable = root.createVariable(name, kind, (name,))
            variable.setncatts(attributes)
            variable[:] = values
        air = root.createVariable("air", "f4", ("time", "level", "lat", "lon"), fill_value=FILL)
        air.units = "K"
        air.standard_name = "air_temperature"
        t, p, y, x = np.meshgrid(HOURS, LEVELS, LATS, LONS, indexing="ij")
        values = 288.0 - 0.045 * (1000.0 - p) - 0.6 * (y - 35.0) + 0.05 * t + rng.normal(0.0, 0.3, t.shape)
        values = np.ma.masked_array(values.astype(np.float32), mask=np.zeros(values.shape, bool))
        values.mask[:, 4, 0:2, 0:3] = True  # high ground under the 1000 hPa level: no data
        values.mask[2, 2, 3, 5] = True  # one value lost at hour 12, 700 hPa
        air[:] = values


def check(path, probe_json, lon, lat, level):
    probe = json.load(open(probe_json))
    with netCDF4.Dataset(path) as root:
        i = int(np.argmin(np.abs(root["lon"][:] - lon)))
        j = int(np.argmin(np.abs(root["lat"][:] - lat)))
        k = int(np.argmin(np.abs(root["level"][:] - level)))
        if (root["lon"][i], root["lat"][j], root["level"][k]) != (np.float32(lon), np.float32(lat), np.float32(level)):
            sys.exit(f"({lon}, {lat}, {level}) is not a node of the file")
        column = root["air"][:, k, j, i]
        times = root["time"]
        masked = np.ma.getmaskarray(column)
        expected = [None if masked[n] else np.float32(column[n]) for n in range(len(column))]
        # The probe writes each value shortest at float32 precision: read back as float32 it is the
        # float32 the file holds, or it differs.
        got = [None if v is None else np.float32(v) for v in probe["values"]]
        problems = []
        if probe["times"] != [float(v) for v in times[:]]:
            problems.append(f"times {probe['times']} against {list(times[:])}")
        if (probe.get("time_units"), probe.get("calendar")) != (times.units, times.calendar):
            problems.append(f"time units {probe.get('time_units')!r}, {probe.get('calendar')!r} against "
                            f"{times.units!r}, {times.calendar!r}")
        if got != expected:
            problems.append(f"values {probe['values']} against netCDF4's {[None if v is None else float(v) for v in expected]}")
        if probe["at"] != [lon, lat, level]:
            problems.append(f"at {probe['at']} against {[lon, lat, level]}")
        if problems:
            sys.exit("; ".join(problems))


if __name__ == "__main__":
    if sys.argv[1] == "write":
        write(sys.argv[2])
    elif sys.argv[1] == "check":
        check(sys.argv[2], sys.argv[3], *(float(v) for v in sys.argv[4:7]))
    else:
        sys.exit(__doc__)
