// tstyles._native: the C++ data model, scenes and renderer for Python. Bad input raises ValueError
// with the message the command line prints; a machine without OpenGL 4.5 raises RuntimeError.
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "tstyles/core/errors.h"

namespace py = pybind11;

PYBIND11_MODULE(_native, module) {
    module.doc() = "Temporal Styles: the C++ core behind the tstyles package (use tstyles, not this module).";
    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const tstyles::InputError& input) {
            PyErr_SetString(PyExc_ValueError, input.what());
        } catch (const tstyles::GlUnavailableError& unavailable) {
            PyErr_SetString(PyExc_RuntimeError, unavailable.what());
        }
    });
    tstyles::python::bindSeries(module);
    tstyles::python::bindConventions(module);
    tstyles::python::bindScene(module);
    tstyles::python::bindImages(module);
    tstyles::python::bindRenderer(module);
}
