#!/usr/bin/env python3
"""A heat plume as a ParaView user keeps it: 8 time-steps on a 64^3 grid, each a zlib-compressed
.vti written by VTK's vtkXMLImageDataWriter, listed in plume.pvd. The gallery picture
docs/gallery/formats/vtk-pvd.png is `tstyles render FOLDER/plume.pvd` of it (docs/readers/vtk-xml.md).

  write_vtk_plume.py FOLDER          (python3-vtk9 and numpy)
"""
import os
import sys

import numpy as np
import vtk
from vtk.util import numpy_support

N = 64
STEPS = 8
SPACING = 0.05  # metres, say: VTK files carry no unit


def fields(step):
    """Temperature of a warm bubble rising along +y and spreading, and its upward velocity. Up is +y
    as ParaView's default camera shows it (and as tstyles' automatic scene shows axes of no meaning)."""
    x_z, up, x_x = np.meshgrid(*(np.linspace(-1.0, 1.0, N),) * 3, indexing="ij")
    x, y, z = x_x, x_z, up  # plume coordinates: z along the rise, x and y across it
    rise = -0.6 + 1.1 * step / (STEPS - 1)
    width = 0.08 + 0.015 * step
    # A mushroom: a cap around the rising centre, a stem below it back to the source.
    radial = np.sqrt(x * x + y * y)
    cap = np.exp(-((radial - (0.12 + 0.04 * step)) ** 2 + (z - rise) ** 2) / (2 * width * width))
    stem = np.exp(-(radial ** 2) / (2 * (0.5 * width) ** 2)) * ((z > -0.9) & (z < rise)) * 0.5
    temperature = 293.0 + 60.0 * np.maximum(cap, stem) * (1.0 - 0.05 * step)
    velocity = np.stack([0.1 * x * cap, 0.8 * cap + stem, 0.1 * y * cap], axis=-1)
    return temperature.astype(np.float32), velocity.astype(np.float32)


def add(data, name, values, active=False):
    flat = values.reshape(-1, 3) if values.ndim == 4 else values.reshape(-1)
    array = numpy_support.numpy_to_vtk(np.ascontiguousarray(flat), deep=True)
    array.SetName(name)
    if active:
        data.GetPointData().SetScalars(array)
    else:
        data.GetPointData().AddArray(array)


def main(folder):
    os.makedirs(os.path.join(folder, "plume"), exist_ok=True)
    lines = []
    for step in range(STEPS):
        temperature, velocity = fields(step)
        data = vtk.vtkImageData()
        data.SetDimensions(N, N, N)
        data.SetSpacing(SPACING, SPACING, SPACING)
        data.SetOrigin(0.0, 0.0, 0.0)
        add(data, "velocity", velocity)
        add(data, "temperature", temperature, active=True)
        name = f"plume/plume_{step:03d}.vti"
        writer = vtk.vtkXMLImageDataWriter()
        writer.SetFileName(os.path.join(folder, name))
        writer.SetInputData(data)
        writer.SetCompressorTypeToZLib()
        writer.SetDataModeToAppended()
        writer.SetEncodeAppendedData(False)
        if writer.Write() != 1:
            raise SystemExit(f"VTK could not write {name}")
        lines.append(f'    <DataSet timestep="{0.25 * step:g}" group="" part="0" file="{name}"/>')
    with open(os.path.join(folder, "plume.pvd"), "w") as pvd:
        pvd.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">\n'
                  "  <Collection>\n" + "\n".join(lines) + "\n  </Collection>\n</VTKFile>\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    main(sys.argv[1])
