// tstyles._native.Renderer: python_renderer.h for Python; images come back as float32 arrays that
// own the renderer's pixels.
#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "image_arrays.h"
#include "python_renderer.h"
#include "tstyles/core/errors.h"

namespace py = pybind11;

namespace tstyles::python {
namespace {

GlBackend backendNamed(const std::string& name) {
    const auto backend = glBackendFromString(name);
    if (!backend) throwInputError("", "--backend", "unknown backend \"" + name + "\"");
    return *backend;
}

// The scene's size unless width or height are given, checked as the command line checks --width.
Scene sizedScene(const SceneHandle& handle, std::optional<int> width, std::optional<int> height) {
    Scene scene = handle.scene;
    for (const auto& [size, option] : {std::pair{width, "--width"}, std::pair{height, "--height"}})
        if (size && (*size < 1 || *size > 16384))
            throwInputError("", option, std::to_string(*size) + " is not in [1 - 16384]");
    scene.width = width.value_or(scene.width);
    scene.height = height.value_or(scene.height);
    return scene;
}

}  // namespace

void bindRenderer(py::module_& module) {
    py::class_<PythonRenderer>(module, "Renderer")
        .def(py::init([](const std::string& backend) { return std::make_unique<PythonRenderer>(backendNamed(backend)); }))
        .def("render",
             [](PythonRenderer& renderer, const SeriesHandle& series, const SceneHandle& scene, std::optional<int> width,
                std::optional<int> height) {
                 return floatPixels(renderer.render(series.series, sizedScene(scene, width, height)));
             })
        .def_property_readonly("uploads", &PythonRenderer::uploads)
        .def_property_readonly("cut_short_rays", &PythonRenderer::lastCutShortRays)
        .def_property_readonly("description", &PythonRenderer::description)
        .def("close", &PythonRenderer::close);
    module.def("total_uploads", &totalUploads);
}

}  // namespace tstyles::python
