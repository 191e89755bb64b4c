#!/usr/bin/env python3
"""Series for the probe's tests: tstyles manifests (float32 values by numpy) whose value at every
place and time is a known linear function, on each grid kind, and a check of `tstyles probe
--json` against it.

  write_probe_samples.py write FOLDER
  write_probe_samples.py check JSON_FILE X Y Z [TOLERANCE]   (exits 1 naming the first difference)

f(x, y, z, t) = 2 + 0.5 x - 0.25 y + 3 z + 10 t, with x, y, z world coordinates and t the time.
Trilinear interpolation reproduces a linear function exactly on rectilinear and uneven grids, and
on a structured grid whose nodes are an affine map of their indices (point location then finds
the same trilinear weights); on a beam fan it is exact at the nodes and along a beam between range
samples. What is left is the float32 density: value ranges of 32 to 36 here, each rounding 2e-6 at most;
the largest error measured was 1.3e-6 (the rotated grid, with the values rounded to float32 as
`probe` writes them), the default tolerance 4e-6.
"""
import json
import math
import os
import sys

import numpy as np

TIMES = (0.0, 1.0, 2.5)
DIMS = (5, 4, 3)


def f(x, y, z, t):
    return 2.0 + 0.5 * x - 0.25 * y + 3.0 * z + 10.0 * t


def rotation_matrix(axis, angle_deg):
    axis = np.asarray(axis, dtype=np.float64)
    axis = axis / np.linalg.norm(axis)
    a = math.radians(angle_deg)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(a) * k + (1 - math.cos(a)) * (k @ k)


def write_manifest(folder, grid, local_nodes, origin=(0.0, 0.0, 0.0), rotation=None, extra_files=None):
    """local_nodes: array (nz, ny, nx, 3) of grid-local node positions, x fastest."""
    os.makedirs(folder, exist_ok=True)
    matrix = rotation_matrix(rotation["axis"], rotation["angle_deg"]) if rotation else np.eye(3)
    world = local_nodes @ matrix.T + np.asarray(origin)
    steps = []
    values_all = []
    for index, time in enumerate(TIMES):
        values = f(world[..., 0], world[..., 1], world[..., 2], time).astype(np.float32)
        values.tofile(os.path.join(folder, f"t{index:02d}.raw"))
        values_all.append(values)
        step = {"time": time, "grid": grid, "values": {"file": f"t{index:02d}.raw", "type": "float32"},
                "placement": {"origin": list(origin)}}
        if rotation:
            step["placement"]["rotation"] = rotation
        steps.append(step)
    low = float(min(v.min() for v in values_all))
    high = float(max(v.max() for v in values_all))
    for name, data in (extra_files or {}).items():
        data.tofile(os.path.join(folder, name))
    with open(os.path.join(folder, "series.json"), "w") as out:
        json.dump({"format": "tstyles-series", "version": 1, "value_range": [low, high], "time_steps": steps}, out)


def lattice(xs, ys, zs):
    z, y, x = np.meshgrid(zs, ys, xs, indexing="ij")
    return np.stack([x, y, z], axis=-1).astype(np.float64)


def write_all(folder):
    spacing = (1.0, 2.0, 0.5)
    xs, ys, zs = (np.arange(n) * s for n, s in zip(DIMS, spacing))
    even = {"type": "rectilinear", "dims": list(DIMS), "spacing": list(spacing)}
    write_manifest(os.path.join(folder, "even"), even, lattice(xs, ys, zs), origin=(1.0, 2.0, 3.0))
    levels = [0.0, 0.2, 1.5]
    uneven = {"type": "rectilinear", "dims": list(DIMS), "spacing": [1.0, 2.0, None], "positions": {"z": levels}}
    write_manifest(os.path.join(folder, "uneven"), uneven, lattice(xs, ys, np.array(levels)), origin=(1.0, 2.0, 3.0))
    write_manifest(os.path.join(folder, "rotated"), even, lattice(xs, ys, zs), origin=(1.0, 2.0, 3.0),
                   rotation={"axis": [1, 1, 0], "angle_deg": 30.0})
    # A sheared structured grid: node (i, j, k) at (i + 0.25 j, 2 j, 0.5 k + 0.1 i), an affine map.
    k, j, i = np.meshgrid(*(np.arange(n, dtype=np.float64) for n in DIMS[::-1]), indexing="ij")
    sheared = np.stack([i + 0.25 * j, 2.0 * j, 0.5 * k + 0.1 * i], axis=-1)
    structured = {"type": "structured", "dims": list(DIMS), "coordinates": {"file": "grid.xyz.f32"}}
    write_manifest(os.path.join(folder, "structured"), structured, sheared, origin=(1.0, 2.0, 3.0),
                   extra_files={"grid.xyz.f32": sheared.astype(np.float32)})
    # A fan of 5 x 4 beams, 6 ranges from 2 to 4.5.
    beam_dims = (5, 4, 6)
    azimuths = np.linspace(-30.0, 30.0, beam_dims[0])
    elevations = np.linspace(-15.0, 15.0, beam_dims[1])
    ranges = np.linspace(2.0, 4.5, beam_dims[2])
    nodes = np.zeros((beam_dims[2], beam_dims[1], beam_dims[0], 3))
    for kk, r in enumerate(ranges):
        for jj, elevation in enumerate(elevations):
            for ii, azimuth in enumerate(azimuths):
                direction = np.array([math.tan(math.radians(azimuth)), math.tan(math.radians(elevation)), 1.0])
                nodes[kk, jj, ii] = r * direction / np.linalg.norm(direction)
    beam = {"type": "beam", "dims": list(beam_dims), "azimuth_deg": [-30.0, 30.0], "elevation_deg": [-15.0, 15.0],
            "range": [2.0, 4.5]}
    write_manifest(os.path.join(folder, "beam"), beam, nodes, origin=(1.0, 2.0, 3.0))
    with open(os.path.join(folder, "beam_nodes.json"), "w") as out:
        json.dump({"node_2_1_3": list(nodes[3, 1, 2] + np.array([1.0, 2.0, 3.0])),
                   "between_2_1_3_and_4": list(0.5 * (nodes[3, 1, 2] + nodes[4, 1, 2]) + np.array([1.0, 2.0, 3.0]))},
                  out)


def check(json_file, x, y, z, tolerance="4e-6"):
    with open(json_file) as source:
        probe = json.load(source)
    x, y, z, tolerance = float(x), float(y), float(z), float(tolerance)
    if probe["times"] != list(TIMES):
        raise SystemExit(f"{json_file}: times {probe['times']}, expected {list(TIMES)}")
    for time, value in zip(TIMES, probe["values"]):
        expected = f(x, y, z, time)
        if value is None or abs(value - expected) > tolerance:
            raise SystemExit(f"{json_file}: at ({x}, {y}, {z}) time {time}: {value}, expected {expected}")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "write":
        write_all(sys.argv[2])
    elif len(sys.argv) in (6, 7) and sys.argv[1] == "check":
        check(*sys.argv[2:])
    else:
        raise SystemExit(__doc__)
