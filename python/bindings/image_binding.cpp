// Images between numpy and the image files `tstyles render` writes. The renderer's pixels are RGBA
// floats with associated (premultiplied) alpha; 8-bit images are what a PNG stores (OpenImageIO
// un-associates alpha when it writes one), so they come from the same PNG writer the CLI uses.
#include <memory>
#include <string>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.h"
#include "image_arrays.h"
#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/image/image_io.h"

namespace py = pybind11;

namespace tstyles::python {

py::array_t<float> floatPixels(Image image) {
    auto pixels = std::make_unique<std::vector<float>>(std::move(image.rgba));
    float* data = pixels->data();
    py::capsule owner(pixels.get(), [](void* vector) { delete static_cast<std::vector<float>*>(vector); });
    pixels.release();
    return py::array_t<float>({image.height, image.width, 4}, data, owner);
}

Image imageFromPixels(const py::array_t<float, py::array::c_style | py::array::forcecast>& pixels) {
    if (pixels.ndim() != 3 || pixels.shape(2) != 4)
        throwInputError("", "image", "expected an array of shape (height, width, 4)");
    Image image(int(pixels.shape(1)), int(pixels.shape(0)));
    std::copy(pixels.data(), pixels.data() + pixels.size(), image.rgba.begin());
    return image;
}

namespace {

using ByteImage = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;

OIIO::ImageSpec straightSpec(int width, int height) {
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the bytes are stored as they are
    return spec;
}

// PNG bytes in memory: premultiplied floats as `writeImage` writes them, or straight 8-bit pixels.
py::bytes encodePng(const OIIO::ImageSpec& spec, OIIO::TypeDesc type, const void* pixels) {
    std::vector<unsigned char> buffer;
    OIIO::Filesystem::IOVecOutput memory(buffer);
    auto output = OIIO::ImageOutput::create("png");
    if (!output) throw std::runtime_error("no PNG writer: " + OIIO::geterror());
    output->set_ioproxy(&memory);
    if (!output->open("memory.png", spec) || !output->write_image(type, pixels) || !output->close())
        throw std::runtime_error("cannot encode a PNG: " + output->geterror());
    return py::bytes(reinterpret_cast<const char*>(buffer.data()), buffer.size());
}

py::bytes encodeFloatPng(const py::array_t<float, py::array::c_style | py::array::forcecast>& pixels) {
    const Image image = imageFromPixels(pixels);
    return encodePng(OIIO::ImageSpec(image.width, image.height, 4, OIIO::TypeDesc::UINT8), OIIO::TypeDesc::FLOAT,
                     image.rgba.data());
}

void requireByteImage(const ByteImage& pixels) {
    if (pixels.ndim() != 3 || pixels.shape(2) != 4)
        throwInputError("", "image", "expected an array of shape (height, width, 4)");
}

py::bytes encodeStraightPng(const ByteImage& pixels) {
    requireByteImage(pixels);
    return encodePng(straightSpec(int(pixels.shape(1)), int(pixels.shape(0))), OIIO::TypeDesc::UINT8, pixels.data());
}

// The 8-bit RGBA an image file stores, alpha not associated (as a PNG keeps it).
py::array_t<std::uint8_t> readStored(std::unique_ptr<OIIO::ImageInput> input, const std::string& name) {
    if (!input) throwInputError(name, "", "cannot read as an image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.nchannels != 4) throwInputError(name, "", "expected RGBA, found " + std::to_string(spec.nchannels) + " channels");
    py::array_t<std::uint8_t> pixels({spec.height, spec.width, 4});
    if (!input->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, pixels.mutable_data()))
        throwInputError(name, "", "cannot read the pixels: " + input->geterror());
    return pixels;
}

OIIO::ImageSpec unassociatedConfig() {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

py::array_t<std::uint8_t> decodePng(const py::bytes& png) {
    const std::string bytes = png;
    OIIO::Filesystem::IOMemReader memory(const_cast<char*>(bytes.data()), bytes.size());
    OIIO::ImageSpec config = unassociatedConfig();
    void* proxy = &memory;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto input = OIIO::ImageInput::create("png", false, &config, &memory);
    OIIO::ImageSpec spec;
    if (!input || !input->open("memory.png", spec, config))
        throw std::runtime_error("cannot decode a PNG: " + (input ? input->geterror() : OIIO::geterror()));
    return readStored(std::move(input), "PNG data");
}

py::array_t<std::uint8_t> readStoredImage(const std::filesystem::path& file) {
    if (!std::filesystem::exists(file)) throwInputError(file, "", "no such file");
    const OIIO::ImageSpec config = unassociatedConfig();
    return readStored(OIIO::ImageInput::open(file.string(), &config), file.string());
}

void writeStraightImage(const ByteImage& pixels, const std::filesystem::path& file) {
    requireByteImage(pixels);
    requireWritableImagePath(file);
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        auto output = OIIO::ImageOutput::create(temporary.string());
        if (!output) throwInputError(file, "", "cannot create the image writer: " + OIIO::geterror());
        if (!output->open(temporary.string(), straightSpec(int(pixels.shape(1)), int(pixels.shape(0)))) ||
            !output->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !output->close())
            throwInputError(file, "", "write failed: " + output->geterror());
    });
}

}  // namespace

void bindImages(py::module_& module) {
    module.def("encode_png", &encodeFloatPng);
    module.def("encode_straight_png", &encodeStraightPng);
    module.def("decode_png", &decodePng);
    module.def("read_image", [](const std::filesystem::path& file) { return floatPixels(readImage(file)); });
    module.def("read_stored_image", &readStoredImage);
    module.def("write_image", [](const py::array_t<float, py::array::c_style | py::array::forcecast>& pixels,
                                 const std::filesystem::path& file) { writeImage(imageFromPixels(pixels), file); });
    module.def("write_straight_image", &writeStraightImage);
}

}  // namespace tstyles::python
