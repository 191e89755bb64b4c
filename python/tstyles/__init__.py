"""Temporal Styles for Python: time-varying volumes from numpy, xarray and files, rendered with
temporal compositors and temporal style transfer functions by the same C++ renderer as the
`tstyles` executable (docs/python.md).

    import tstyles, xarray
    series = tstyles.from_xarray(xarray.open_dataset("ocean.nc")["thetao"])
    scene = tstyles.Scene.automatic(series)
    scene.compositor = "temporal-max-change"
    image = tstyles.render(series, scene, 640, 480)   # a numpy (480, 640, 4) uint8 array
    image.save("ocean.png")
"""

from .rendering import Image, Renderer, read_image, render, upload_count
from .scene import Scene, built_in_styles
from .series import Series, from_xarray, open, reader_options

__all__ = ["Image", "Renderer", "Scene", "Series", "built_in_styles", "from_xarray", "open", "read_image", "reader_options", "render",
           "upload_count"]
