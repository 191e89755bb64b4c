#!/usr/bin/env python3
"""A resampled ocean model's sea temperature as a float OME-TIFF (tifffile), with NaN over land: 6
daily time points of 20 depth levels of 160 x 120 cells, a warm eddy drifting west past an island,
a coastline along the east, and a sea floor that rises toward the coast (cells below it are NaN
too). The gallery picture docs/gallery/formats/ome-tiff-nan.png is `tstyles render FILE` of it
(docs/readers/tiff.md).

  write_ome_tiff_eddy.py FILE.ome.tif          (python3-tifffile and numpy)
"""
import sys

import numpy as np
import tifffile

T, Z, Y, X = 6, 20, 120, 160


def temperature():
    t, z, y, x = np.meshgrid(np.arange(T), np.arange(Z), np.arange(Y), np.arange(X), indexing="ij")
    depth = z / (Z - 1)  # 0 at the surface, 1 at the deepest level
    values = 18.0 - 12.0 * depth ** 0.6 + 0.4 * np.sin(x / 9.0) * np.cos(y / 11.0)
    # A warm-core eddy drifting west and sinking a little, strongest near the surface.
    centre_x = 115.0 - 9.0 * t
    centre_y = 60.0 + 4.0 * np.sin(t / 2.0)
    radius = 14.0 + 0.8 * t
    eddy = np.exp(-((x - centre_x) ** 2 + (y - centre_y) ** 2) / (2 * radius ** 2))
    values += 4.0 * eddy * np.exp(-depth / 0.35)
    values += 0.15 * np.random.default_rng(3).standard_normal(values.shape)
    # Land: a coast along the east with a bay, an island, and a floor rising toward the coast.
    coast = 140.0 + 8.0 * np.sin(y / 13.0)
    island = (x - 60.0) ** 2 / 90.0 + (y - 35.0) ** 2 / 50.0 < 1.0
    floor = 1.0 - 0.85 * np.clip((x - 20.0) / (coast - 20.0), 0.0, 1.0) ** 3
    land = (x > coast) | island | (depth > floor)
    values[land] = np.nan
    return values.astype(np.float32)


def main(path):
    tifffile.imwrite(path, temperature(), photometric="minisblack",
                     metadata={"axes": "TZYX", "PhysicalSizeX": 5.0, "PhysicalSizeXUnit": "km",
                               "PhysicalSizeY": 5.0, "PhysicalSizeYUnit": "km",
                               "PhysicalSizeZ": 25.0, "PhysicalSizeZUnit": "m",
                               "TimeIncrement": 1.0, "TimeIncrementUnit": "d"}, ome=True)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    main(sys.argv[1])
