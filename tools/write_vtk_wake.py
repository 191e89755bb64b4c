#!/usr/bin/env python3
"""A cylinder's wake as a CFD code writes it for ParaView: 6 numbered legacy VTK files
(wake/wake_0000.vtk ...), each a RECTILINEAR_GRID of 112 x 56 x 20 with grid lines packed near the
cylinder and the wake's centre line, binary, written by VTK's vtkRectilinearGridWriter. The point
array is the vorticity magnitude of a Karman vortex street shed by the cylinder (vortices of
alternating sign, each bent along the span), with 3 % noise; inside the cylinder it is NaN (no
flow). The gallery picture docs/gallery/formats/vtk-legacy.png is `tstyles render FOLDER/wake/*.vtk`
of it (docs/readers/vtk-xml.md).

  write_vtk_wake.py FOLDER          (python3-vtk9 and numpy)
"""
import os
import sys

import numpy as np
import vtk
from vtk.util import numpy_support

STEPS = 6
DIAMETER = 1.0


def stretched(start, end, count, centre, strength):
    """Grid lines from start to end, closer together near centre."""
    u = np.linspace(-1.0, 1.0, count)
    lines = np.sinh(strength * u) / np.sinh(strength)
    scaled = centre + np.where(lines < 0, (centre - start) * lines, (end - centre) * lines)
    return scaled


X = stretched(-3.0, 16.0, 112, 0.0, 2.2)
Y = stretched(-4.0, 4.0, 56, 0.0, 1.8)
Z = np.linspace(0.0, 4.0, 20)


def vorticity(step, rng):
    z, y, x = np.meshgrid(Z, Y, X, indexing="ij")
    spacing = 4.3 * DIAMETER  # between vortices of one row
    speed = 0.85  # convection speed, diameters per time unit
    time = 1.2 * step
    field = np.zeros_like(x)
    for k in range(-1, 5):
        for row, sign in ((0, 1.0), (1, -1.0)):
            centre_x = 1.2 + k * spacing + row * 0.5 * spacing + speed * time % spacing
            if centre_x < 0.8:
                continue
            centre_y = sign * 0.45 * (1.0 - np.exp(-(centre_x - 0.5) / 3.0))
            # The vortex bends along the span (oblique shedding), grows and weakens downstream.
            bend = 0.35 * np.sin(2.0 * np.pi * z / 4.0 + 0.6 * k)
            radius = 0.22 + 0.02 * centre_x
            strength = 2.5 * np.exp(-centre_x / 14.0)
            distance = (x - centre_x - bend) ** 2 + (y - centre_y) ** 2
            field += sign * strength * np.exp(-distance / (2 * radius * radius))
    # Shear layers leaving the cylinder's sides.
    layer = np.exp(-((np.abs(y) - 0.5) ** 2) / 0.01) * np.exp(-np.maximum(x, 0.0) / 1.5) * (x > -0.2)
    magnitude = np.abs(field) + 2.0 * layer
    magnitude *= 1.0 + 0.03 * rng.standard_normal(magnitude.shape)
    magnitude[x * x + y * y < (0.5 * DIAMETER) ** 2] = np.nan
    return magnitude.astype(np.float32)


def main(folder):
    os.makedirs(os.path.join(folder, "wake"), exist_ok=True)
    rng = np.random.default_rng(7)
    for step in range(STEPS):
        grid = vtk.vtkRectilinearGrid()
        grid.SetDimensions(len(X), len(Y), len(Z))
        for axis, values in enumerate((X, Y, Z)):
            coordinates = numpy_support.numpy_to_vtk(values.astype(np.float32), deep=True)
            (grid.SetXCoordinates, grid.SetYCoordinates, grid.SetZCoordinates)[axis](coordinates)
        array = numpy_support.numpy_to_vtk(vorticity(step, rng).reshape(-1), deep=True)
        array.SetName("vorticity")
        grid.GetPointData().SetScalars(array)
        name = os.path.join(folder, "wake", f"wake_{step:04d}.vtk")
        writer = vtk.vtkRectilinearGridWriter()
        writer.SetFileName(name)
        writer.SetInputData(grid)
        writer.SetFileTypeToBinary()
        if writer.Write() != 1:
            raise SystemExit(f"VTK could not write {name}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    main(sys.argv[1])
