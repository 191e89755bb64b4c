"""Renderer and Image: headless rendering to numpy arrays that show themselves in Jupyter."""

import os
import warnings

import numpy as np

from . import _native
from .scene import Scene


class Image(np.ndarray):
    """A rendered image: a (height, width, 4) numpy array, rows top to bottom.

    float32 images hold the renderer's RGBA with premultiplied alpha, exactly as `tstyles render`
    writes EXR files; uint8 images hold what its PNG files store (straight alpha, 8 bits). In
    Jupyter an image displays itself (_repr_png_); save() writes any format the CLI writes.
    """

    def __array_finalize__(self, source):
        # Only the whole image keeps the renderer's float pixels; a slice or a changed copy is new.
        premultiplied = getattr(source, "_premultiplied", None)
        keep = premultiplied is not None and self.shape == source.shape and self.dtype == source.dtype
        self._premultiplied = premultiplied if keep else None

    @classmethod
    def _from_pixels(cls, premultiplied, dtype):
        if np.dtype(dtype) == np.float32:
            image = premultiplied.view(cls)
        elif np.dtype(dtype) == np.uint8:
            image = _native.decode_png(_native.encode_png(premultiplied)).view(cls)
        else:
            raise ValueError(f"dtype: expected uint8 or float32, got {np.dtype(dtype)}")
        image._premultiplied = premultiplied
        return image

    def png(self):
        """The image as PNG bytes: the file `tstyles render -o x.png` writes for it."""
        if self._premultiplied is not None:
            return _native.encode_png(self._premultiplied)
        if self.dtype == np.uint8:
            return _native.encode_straight_png(np.asarray(self))
        return _native.encode_png(np.asarray(self, dtype=np.float32))

    def _repr_png_(self):
        return self.png()

    def save(self, path):
        """Writes the image (.png, .tif, .exr, ...) as `tstyles render` would, through a temporary file."""
        path = os.fspath(path)
        if self._premultiplied is not None:
            _native.write_image(self._premultiplied, path)
        elif self.dtype == np.uint8:
            _native.write_straight_image(np.asarray(self), path)
        else:
            _native.write_image(np.asarray(self, dtype=np.float32), path)


def read_image(path, dtype="float32"):
    """An image file: float32 premultiplied RGBA (as the renderer makes it), or uint8 as the file stores it."""
    if np.dtype(dtype) == np.float32:
        return np.asarray(_native.read_image(os.fspath(path))).view(Image)
    if np.dtype(dtype) == np.uint8:
        return np.asarray(_native.read_stored_image(os.fspath(path))).view(Image)
    raise ValueError(f"dtype: expected uint8 or float32, got {np.dtype(dtype)}")


class Renderer:
    """Headless rendering (EGL, else OSMesa; backend="egl" or "osmesa" forces one).

    A Renderer keeps its OpenGL state and the last series it uploaded: rendering the same series
    again (other cameras, transfer functions, compositors) uploads nothing, as long as the scene's
    display settings (orientation, aspect, vertical exaggeration) stay the same. All Renderers of a
    process share one OpenGL context; use them from the thread that made the first one.
    """

    def __init__(self, backend="auto"):
        self._native = _native.Renderer(backend)

    def render(self, series, scene=None, width=None, height=None, dtype="uint8"):
        """The scene (default: the automatic scene of the series) on the series, as an Image.

        width and height override the scene's image size. The series' own data is shown, whatever
        dataset the scene names.
        """
        if scene is None:
            scene = Scene.automatic(series)
        pixels = self._native.render(series._native, scene._native, width, height)
        cut_short = self._native.cut_short_rays
        if cut_short:
            warnings.warn(f"{cut_short} of the image's rays were cut short by the OpenGL driver's limit on loop "
                          f"passes per pixel ({self.description}), so those pixels are incomplete; a larger "
                          "raycast.step takes fewer samples per ray", RuntimeWarning, stacklevel=2)
        return Image._from_pixels(pixels, dtype)

    @property
    def uploads(self):
        """How many times this renderer uploaded a series to the GPU."""
        return self._native.uploads

    @property
    def description(self):
        """The backend and OpenGL renderer, e.g. "EGL surfaceless: llvmpipe (...), OpenGL 4.5"."""
        return self._native.description

    def close(self):
        """Gives the GPU memory back now instead of when the object goes."""
        self._native.close()

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.close()


_default_renderer = None


def render(series, scene=None, width=None, height=None, dtype="uint8", backend="auto"):
    """Renderer.render on a renderer kept by the module, made on first use."""
    global _default_renderer
    if _default_renderer is None:
        _default_renderer = Renderer(backend)
    return _default_renderer.render(series, scene, width, height, dtype)


def upload_count():
    """Series uploads by every Renderer of this process so far."""
    return _native.total_uploads()
