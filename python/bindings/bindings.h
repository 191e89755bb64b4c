// The pieces of the tstyles._native extension module, one per concept; module.cpp puts them
// together. Python sees thin handles; the classes users meet are in python/tstyles/.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"

namespace tstyles::python {

// A series is immutable once made and shared: by the Python object, by the density views it hands
// out and by the renderer that shows it, so none of them copies it.
using SharedSeries = std::shared_ptr<const Series>;

struct SeriesHandle {
    SharedSeries series;
};

struct SceneHandle {
    Scene scene;
    std::vector<std::string> explanation;  // the automatic scene's choices; empty otherwise
};

void bindSeries(pybind11::module_& module);
void bindConventions(pybind11::module_& module);
void bindScene(pybind11::module_& module);
void bindImages(pybind11::module_& module);
void bindRenderer(pybind11::module_& module);

}  // namespace tstyles::python
