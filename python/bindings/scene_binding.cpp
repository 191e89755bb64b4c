// Scenes for Python: JSON in and out through the scene reader and writer, so a scene made in Python
// is checked key by key like a scene file; the automatic scene of a series. python/tstyles/scene.py
// builds the dict interface on these.
#include <filesystem>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.h"
#include "tstyles/render/style_library.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/scene_keys.h"

namespace py = pybind11;

namespace tstyles::python {

void bindScene(py::module_& module) {
    py::class_<SceneHandle>(module, "Scene")
        .def(py::init<>())
        .def("__eq__", [](const SceneHandle& a, const SceneHandle& b) { return a.scene == b.scene; })
        .def_readonly("explanation", &SceneHandle::explanation)
        .def("to_json", [](const SceneHandle& s) { return sceneToJson(s.scene, std::filesystem::current_path()); });

    // `origin` names the text in messages; a relative dataset path stays relative to the current folder.
    module.def("scene_from_json", [](const std::string& json, const std::string& origin) {
        return SceneHandle{parseScene(json, origin), {}};
    });
    module.def("load_scene", [](const std::filesystem::path& file) { return SceneHandle{loadScene(file), {}}; });
    module.def("save_scene", [](const SceneHandle& s, const std::filesystem::path& file) { saveScene(s.scene, file); });
    module.def("automatic_scene", [](const SeriesHandle& s) {
        AutomaticScene automatic = automaticScene(*s.series, s.series->manifestPath);
        return SceneHandle{std::move(automatic.scene), std::move(automatic.explanation)};
    });
    module.def("built_in_styles", &builtInStyleNames);
    // The table of scene keys (scene_keys.h): path, type, default and what each takes, as
    // docs/scene-format.md lists them; scene.py's docstrings are made from it.
    module.def("scene_keys", [] {
        std::vector<py::dict> keys;
        for (const SceneKey& key : sceneKeys()) {
            py::dict entry;
            entry["path"] = std::string(key.path);
            entry["type"] = std::string(key.type);
            entry["default"] = std::string(key.defaultText);
            entry["allowed"] = allowedText(key);
            entry["whole"] = key.numeric && key.numeric->whole;
            keys.push_back(std::move(entry));
        }
        return keys;
    });
}

}  // namespace tstyles::python
