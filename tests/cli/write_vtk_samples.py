#!/usr/bin/env python3
"""VTK XML and legacy (.vtk) files for the vtk readers' tests, written by VTK's own writers
(python3-vtk9), and a check of the raw values `tstyles convert` wrote against the values the files hold.

  write_vtk_samples.py write FOLDER
  write_vtk_samples.py check RAW_FILE ARRAY STEP [mirror-x]   (exits 1 naming the first difference)

Known values on a 5 x 4 x 3 grid (i, j, k from 0, x fastest), time-step t:
  temperature (Float32) = 0.5 i + 2 j + 10 k + 100 t
  pressure    (Int16)   = i j - 7 k - 3 t
  label       (UInt8)   = i + j + k + t
  velocity    (Float64, 3 components) = (i, j, k + t): read as its magnitude
"""
import json
import os
import sys

import numpy as np
import vtk
from vtk.util import numpy_support
from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase

DIMS = (5, 4, 3)  # x, y, z


def known(array, step):
    k, j, i = np.meshgrid(*(np.arange(n) for n in DIMS[::-1]), indexing="ij")
    if array == "temperature":
        return (0.5 * i + 2 * j + 10 * k + 100 * step).astype(np.float32)
    if array == "pressure":
        return (i * j - 7 * k - 3 * step).astype(np.int16)
    if array == "label":
        return (i + j + k + step).astype(np.uint8)
    if array == "velocity":
        return np.stack([i, j, k + step], axis=-1).astype(np.float64)
    if array == "velocity-magnitude":
        return np.sqrt(i * i + j * j + (k + step) ** 2.0).astype(np.float32)
    raise SystemExit(f"no known array {array}")


def add_array(data, name, values, active=False):
    flat = values.reshape(-1, values.shape[-1]) if values.ndim == 4 else values.reshape(-1)
    array = numpy_support.numpy_to_vtk(np.ascontiguousarray(flat), deep=True)
    array.SetName(name)
    if active:
        data.GetPointData().SetScalars(array)
    else:
        data.GetPointData().AddArray(array)


def image(step, origin=(0.0, 0.0, 0.0), spacing=(0.5, 1.0, 2.0), arrays=("temperature", "pressure", "label")):
    data = vtk.vtkImageData()
    data.SetDimensions(*DIMS)
    data.SetOrigin(*origin)
    data.SetSpacing(*spacing)
    # The active Scalars is the last array: the reader must follow the attribute, not the order.
    for name in arrays[1:]:
        add_array(data, name, known(name, step))
    add_array(data, "velocity", known("velocity", step))
    add_array(data, arrays[0], known(arrays[0], step), active=True)
    return data


def write(writer, data, path, mode="Binary", compressor="None", header="UInt32", encode=True, big=False,
          block=None):
    writer.SetFileName(path)
    writer.SetInputData(data)
    getattr(writer, "SetDataModeTo" + mode)()
    getattr(writer, "SetCompressorTypeTo" + compressor)()
    getattr(writer, "SetHeaderTypeTo" + header)()
    writer.SetEncodeAppendedData(encode)
    if big:
        writer.SetByteOrderToBigEndian()
    if block:
        writer.SetBlockSize(block)
    if writer.Write() != 1:
        raise SystemExit(f"VTK could not write {path}")


# name: (data mode, compressor, header type, encode appended data, big-endian, block size)
VARIANTS = {
    "ascii": ("Ascii", "None", "UInt32", True, False, None),
    "binary": ("Binary", "None", "UInt32", True, False, None),
    "binary_uint64": ("Binary", "None", "UInt64", True, False, None),
    "binary_zlib": ("Binary", "ZLib", "UInt32", True, False, None),
    "binary_zlib_blocks": ("Binary", "ZLib", "UInt64", True, False, 64),
    "binary_lz4": ("Binary", "LZ4", "UInt64", True, False, None),
    "binary_lzma": ("Binary", "LZMA", "UInt32", True, False, None),
    "appended_raw": ("Appended", "None", "UInt64", False, False, None),
    "appended_raw_zlib": ("Appended", "ZLib", "UInt32", False, False, 96),
    "appended_raw_lz4": ("Appended", "LZ4", "UInt32", False, False, None),
    "appended_base64": ("Appended", "None", "UInt32", True, False, None),
    "appended_base64_lzma": ("Appended", "LZMA", "UInt64", True, False, 128),
    "big_endian": ("Binary", "None", "UInt32", True, True, None),
    "big_endian_appended_zlib": ("Appended", "ZLib", "UInt64", False, True, None),
}


def write_all(folder):
    os.makedirs(folder, exist_ok=True)
    for name, (mode, compressor, header, encode, big, block) in VARIANTS.items():
        write(vtk.vtkXMLImageDataWriter(), image(0), os.path.join(folder, name + ".vti"), mode, compressor, header,
              encode, big, block)
    # No active Scalars (pressure is the first array): the first array of one component is read.
    data = image(0)
    data.GetPointData().SetActiveScalars(None)
    write(vtk.vtkXMLImageDataWriter(), data, os.path.join(folder, "no_active.vti"))
    # Only the vector: nothing of one component to pick by default.
    vector_only = vtk.vtkImageData()
    vector_only.SetDimensions(*DIMS)
    add_array(vector_only, "velocity", known("velocity", 0))
    write(vtk.vtkXMLImageDataWriter(), vector_only, os.path.join(folder, "vector_only.vti"))
    # A rotation (90 degrees about z) and a reflection (x reversed) in the Direction matrix.
    rotated = image(0, origin=(1.0, 2.0, 3.0))
    rotated.SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, 1)
    write(vtk.vtkXMLImageDataWriter(), rotated, os.path.join(folder, "rotated.vti"), compressor="ZLib")
    mirrored = image(0, origin=(1.0, 2.0, 3.0))
    mirrored.SetDirectionMatrix(-1, 0, 0, 0, 1, 0, 0, 0, 1)
    write(vtk.vtkXMLImageDataWriter(), mirrored, os.path.join(folder, "mirrored.vti"))
    # An extent that does not start at 0: the first point sits at Origin + Spacing * start.
    offset = image(0, origin=(1.0, 2.0, 3.0))
    offset.SetExtent(2, 6, 0, 3, 1, 3)
    write(vtk.vtkXMLImageDataWriter(), offset, os.path.join(folder, "offset_extent.vti"))
    write_series(folder)
    write_structured(folder)
    write_pieces(folder)
    write_rectilinear(folder)
    write_legacy(folder)
    write_parallel(folder)


def write_series(folder):
    """plume.pvd and plume.vti.series: three time-steps whose origins move along x."""
    os.makedirs(os.path.join(folder, "plume"), exist_ok=True)
    times = [0.5, 1.5, 4.0]
    entries = []
    for step, time in enumerate(times):
        name = f"plume/plume_{step}.vti"
        write(vtk.vtkXMLImageDataWriter(), image(step, origin=(0.25 * step, 1.0, 2.0)), os.path.join(folder, name),
              mode="Appended", compressor="ZLib", encode=False)
        entries.append((time, name))
    with open(os.path.join(folder, "plume.pvd"), "w") as pvd:
        pvd.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">\n'
                  "  <Collection>\n")
        for time, name in entries:
            pvd.write(f'    <DataSet timestep="{time}" group="" part="0" file="{name}"/>\n')
        pvd.write("  </Collection>\n</VTKFile>\n")
    with open(os.path.join(folder, "plume.vti.series"), "w") as series:
        json.dump({"file-series-version": "1.0", "files": [{"name": n, "time": t} for t, n in entries]}, series)


def sheared_grid():
    """A sheared but valid curvilinear grid (x leans with y), temperature on its points."""
    grid = vtk.vtkStructuredGrid()
    grid.SetDimensions(*DIMS)
    points = vtk.vtkPoints()
    for k in range(DIMS[2]):
        for j in range(DIMS[1]):
            for i in range(DIMS[0]):
                points.InsertNextPoint(i + 0.25 * j, j, 2.0 * k)
    grid.SetPoints(points)
    add_array(grid, "temperature", known("temperature", 0), active=True)
    return grid


def write_structured(folder):
    """grid.vts: the sheared grid."""
    write(vtk.vtkXMLStructuredGridWriter(), sheared_grid(), os.path.join(folder, "grid.vts"), compressor="ZLib")


# The rectilinear grid's coordinates: x and y even, z uneven (levels closer near the surface).
RECT_COORDINATES = ((10.0, 10.5, 11.0, 11.5, 12.0), (-2.0, -1.0, 0.0, 1.0), (0.0, 1.0, 3.0))


def depth_grid():
    """A RectilinearGrid with uneven z, the known arrays of step 0 on its points."""
    grid = vtk.vtkRectilinearGrid()
    grid.SetDimensions(*DIMS)
    for axis, values in enumerate(RECT_COORDINATES):
        array = numpy_support.numpy_to_vtk(np.array(values, dtype=np.float64), deep=True)
        (grid.SetXCoordinates, grid.SetYCoordinates, grid.SetZCoordinates)[axis](array)
    add_array(grid, "pressure", known("pressure", 0))
    add_array(grid, "temperature", known("temperature", 0), active=True)
    return grid


def write_rectilinear(folder):
    """depth.vtr (appended, zlib) and depth_ascii.vtr: the depth grid."""
    grid = depth_grid()
    write(vtk.vtkXMLRectilinearGridWriter(), grid, os.path.join(folder, "depth.vtr"), "Appended", "ZLib")
    write(vtk.vtkXMLRectilinearGridWriter(), grid, os.path.join(folder, "depth_ascii.vtr"), "Ascii")


def write_legacy_file(writer, data, path, binary=True, version=None):
    writer.SetFileName(path)
    writer.SetInputData(data)
    if version:
        writer.SetFileVersion(version)
    if binary:
        writer.SetFileTypeToBinary()
    else:
        writer.SetFileTypeToASCII()
    if writer.Write() != 1:
        raise SystemExit(f"VTK could not write {path}")


def write_legacy(folder):
    """Legacy .vtk files: the known arrays of step 0 as ASCII and BINARY STRUCTURED_POINTS (version
    5.1, VTK 9's default, and 4.2), a STRUCTURED_GRID and a RECTILINEAR_GRID, and a series of three
    with legacy.pvd. The legacy writers put the active scalars (temperature) in SCALARS and the other
    point arrays in a FIELD."""
    for name, binary, version in (("legacy_ascii", False, None), ("legacy_binary", True, None),
                                  ("legacy_binary_42", True, 42)):
        write_legacy_file(vtk.vtkStructuredPointsWriter(), image(0), os.path.join(folder, name + ".vtk"), binary,
                          version)
    write_legacy_file(vtk.vtkStructuredGridWriter(), sheared_grid(), os.path.join(folder, "legacy_grid.vtk"))
    write_legacy_file(vtk.vtkRectilinearGridWriter(), depth_grid(), os.path.join(folder, "legacy_depth.vtk"), False)
    os.makedirs(os.path.join(folder, "legacy_series"), exist_ok=True)
    times = [0.5, 1.5, 4.0]
    with open(os.path.join(folder, "legacy.pvd"), "w") as pvd:
        pvd.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">\n'
                  "  <Collection>\n")
        for step, time in enumerate(times):
            name = f"legacy_series/flow_{step:04d}.vtk"
            write_legacy_file(vtk.vtkStructuredPointsWriter(), image(step, origin=(0.25 * step, 1.0, 2.0)),
                              os.path.join(folder, name))
            pvd.write(f'    <DataSet timestep="{time}" group="" part="0" file="{name}"/>\n')
        pvd.write("  </Collection>\n</VTKFile>\n")


def write_pieces(folder):
    """pieces.vti: VTK's analytic source written in 3 pieces (each its own extent), and whole.vti in one."""
    for name, pieces in (("pieces.vti", 3), ("whole.vti", 1)):
        source = vtk.vtkRTAnalyticSource()
        source.SetWholeExtent(0, 9, 0, 7, 0, 5)
        writer = vtk.vtkXMLImageDataWriter()
        writer.SetFileName(os.path.join(folder, name))
        writer.SetInputConnection(source.GetOutputPort())
        writer.SetNumberOfPieces(pieces)
        writer.SetDataModeToBinary()
        if writer.Write() != 1:
            raise SystemExit(f"VTK could not write {name}")


class RectilinearSource(VTKPythonAlgorithmBase):
    """The depth grid of write_rectilinear as a streaming source: it makes any sub-extent asked for,
    as a simulation's processes each make theirs, so VTK's parallel writer can split it."""

    def __init__(self):
        VTKPythonAlgorithmBase.__init__(self, nInputPorts=0, nOutputPorts=1, outputType="vtkRectilinearGrid")

    def RequestInformation(self, request, in_info, out_info):
        info = out_info.GetInformationObject(0)
        info.Set(vtk.vtkStreamingDemandDrivenPipeline.WHOLE_EXTENT(), (0, DIMS[0] - 1, 0, DIMS[1] - 1, 0, DIMS[2] - 1), 6)
        info.Set(vtk.vtkAlgorithm.CAN_PRODUCE_SUB_EXTENT(), 1)
        return 1

    def RequestData(self, request, in_info, out_info):
        info = out_info.GetInformationObject(0)
        x0, x1, y0, y1, z0, z1 = info.Get(vtk.vtkStreamingDemandDrivenPipeline.UPDATE_EXTENT())
        grid = vtk.vtkRectilinearGrid.GetData(out_info)
        grid.SetExtent(x0, x1, y0, y1, z0, z1)
        for axis, (start, end) in enumerate(((x0, x1), (y0, y1), (z0, z1))):
            values = np.array(RECT_COORDINATES[axis][start:end + 1], dtype=np.float64)
            (grid.SetXCoordinates, grid.SetYCoordinates, grid.SetZCoordinates)[axis](
                numpy_support.numpy_to_vtk(values, deep=True))
        temperature = known("temperature", 0)[z0:z1 + 1, y0:y1 + 1, x0:x1 + 1]
        add_array(grid, "temperature", temperature, active=True)
        return 1


def write_parallel(folder):
    """parallel/: VTK's parallel writers (one file per piece, listed by a .pvti, .pvtr or .pvts):
    the analytic source of write_pieces in 3 pieces (compare whole.vti), the depth grid in 2, and
    a structured grid of the analytic source in 3."""
    os.makedirs(os.path.join(folder, "parallel"), exist_ok=True)

    def write_parallel_file(writer, port, name, pieces):
        writer.SetFileName(os.path.join(folder, "parallel", name))
        writer.SetInputConnection(port)
        writer.SetNumberOfPieces(pieces)
        writer.SetStartPiece(0)
        writer.SetEndPiece(pieces - 1)
        writer.SetDataModeToAppended()
        writer.SetCompressorTypeToZLib()
        if writer.Write() != 1:
            raise SystemExit(f"VTK could not write {name}")

    source = vtk.vtkRTAnalyticSource()
    source.SetWholeExtent(0, 9, 0, 7, 0, 5)
    write_parallel_file(vtk.vtkXMLPImageDataWriter(), source.GetOutputPort(), "pieces.pvti", 3)
    depth = RectilinearSource()  # kept: the pipeline holds no reference to a Python algorithm
    write_parallel_file(vtk.vtkXMLPRectilinearGridWriter(), depth.GetOutputPort(), "depth.pvtr", 2)
    points = vtk.vtkImageDataToPointSet()
    points.SetInputConnection(source.GetOutputPort())
    write_parallel_file(vtk.vtkXMLPStructuredGridWriter(), points.GetOutputPort(), "pieces.pvts", 3)


def check(raw_file, array, step, order="as-written"):
    expected = known(array, int(step)).astype(np.float32)
    if order == "mirror-x":
        expected = expected[:, :, ::-1]
    expected = expected.reshape(-1)
    actual = np.fromfile(raw_file, dtype="<f4")
    if actual.size != expected.size:
        raise SystemExit(f"{raw_file}: {actual.size} values, expected {expected.size}")
    differ = np.nonzero(actual != expected)[0]
    if differ.size:
        first = differ[0]
        raise SystemExit(f"{raw_file}: value {first} is {actual[first]}, expected {expected[first]}")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "write":
        write_all(sys.argv[2])
    elif len(sys.argv) in (5, 6) and sys.argv[1] == "check":
        check(*sys.argv[2:])
    else:
        raise SystemExit(__doc__)
