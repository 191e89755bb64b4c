// Images and numpy arrays: the renderer's RGBA floats handed to Python without a copy.
#pragma once

#include <pybind11/numpy.h>

#include "tstyles/image/image.h"

namespace tstyles::python {

// A (height, width, 4) float32 array that owns the image's pixels (moved, not copied).
pybind11::array_t<float> floatPixels(Image image);

// An Image from a (height, width, 4) array of premultiplied RGBA.
Image imageFromPixels(const pybind11::array_t<float, pybind11::array::c_style | pybind11::array::forcecast>& pixels);

}  // namespace tstyles::python
