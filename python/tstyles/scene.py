"""Scene: the content of a scene file (docs/scene-format.md) as a Python object and as a dict."""

import copy
import json
import os

from . import _native

# Where a scene made in Python names no dataset: the command line's stand-in for "none".
_NO_DATASET = "-"


class Scene:
    """How a series is seen and classified: camera, STF, TSTFs (with lit-sphere styles), compositor.

    Every change goes through the scene reader, so a bad value raises ValueError with the message
    `tstyles render` prints for the same key in a file. Top-level keys read and write as items
    (scene["camera"]), the common ones also as attributes (scene.compositor, scene.width).
    """

    def __init__(self, content=None):
        """A scene from a dict (the JSON of a scene file), JSON text, or the defaults."""
        if content is None:
            content = {}  # the reader's defaults, read as a file without a dataset would be
        if isinstance(content, str):
            self._native = _native.scene_from_json(content, "scene")
        else:
            self._native = _from_dict(content)

    @classmethod
    def _wrap(cls, native):
        scene = cls.__new__(cls)
        scene._native = native
        return scene

    @classmethod
    def load(cls, path):
        """Reads a scene file; a relative dataset path is taken from the file's folder."""
        return cls._wrap(_native.load_scene(os.fspath(path)))

    @classmethod
    def automatic(cls, series):
        """The automatic scene of a series (docs/automatic-scene.md): what `tstyles render FILE` draws."""
        return cls._wrap(_native.automatic_scene(series._native))

    def save(self, path):
        """Writes the scene file (through a temporary file and a rename)."""
        _native.save_scene(self._native, os.fspath(path))

    def to_json(self):
        return self._native.to_json()

    def to_dict(self):
        """The scene file's content; changing the dict does not change the scene (assign it back)."""
        return json.loads(self.to_json())

    @property
    def explanation(self):
        """For an automatic scene as made: what was chosen and why, one line each (empty once changed)."""
        return list(self._native.explanation)

    def __getitem__(self, key):
        return self.to_dict()[key]

    def __setitem__(self, key, value):
        self.update({key: value})

    def update(self, changes):
        """Sets several top-level keys at once, checked together."""
        content = self.to_dict()
        content.update(copy.deepcopy(changes))
        self._native = _from_dict(content)

    def set(self, path, value):
        """Sets one value by its path as error messages name it: scene.set("tstf.gradient.range", [0, 0.3])."""
        content = self.to_dict()
        keys = path.split(".")
        target = content
        for key in keys[:-1]:
            target = target.setdefault(key, {})
        target[keys[-1]] = copy.deepcopy(value)
        self._native = _from_dict(content)

    def copy(self):
        return Scene._wrap(_native.scene_from_json(self.to_json(), "scene"))

    def __eq__(self, other):
        return isinstance(other, Scene) and self._native == other._native

    def __repr__(self):
        return f"<tstyles.Scene {self.compositor}, {self.width}x{self.height}>"

    @staticmethod
    def keys():
        """Every key of a scene file with its type, default and what it takes (docs/scene-format.md)."""
        return [dict(key) for key in _native.scene_keys()]

    # The keys most scripts change, as attributes: each reads and writes the key at its path, and
    # its docstring is the key's line of the scene reader's table (_key_doc).
    compositor = property(lambda self: self["compositor"], lambda self, v: self.__setitem__("compositor", v))
    # "composite" where the file leaves the ray out; a name, or a dict with the mode and its options.
    ray = property(lambda self: self.to_dict().get("ray", "composite"), lambda self, v: self.__setitem__("ray", v))
    final_mode = property(lambda self: self["final"], lambda self, v: self.__setitem__("final", v))
    camera = property(lambda self: self["camera"], lambda self, v: self.__setitem__("camera", v))
    stf = property(lambda self: self["stf"], lambda self, v: self.__setitem__("stf", v))
    index_tstf = property(lambda self: self["tstf"]["index"], lambda self, v: self.set("tstf.index", v))
    gradient_tstf = property(lambda self: self["tstf"]["gradient"], lambda self, v: self.set("tstf.gradient", v))
    width = property(lambda self: self["image"]["width"], lambda self, v: self.set("image.width", v))
    height = property(lambda self: self["image"]["height"], lambda self, v: self.set("image.height", v))
    background = property(lambda self: self["image"]["background"], lambda self, v: self.set("image.background", v))

    @property
    def styles(self):
        """The styles the scene's transfer functions use (built-in names or image files)."""
        content = self.to_dict()
        curves = [content.get("stf", {})] + list(content.get("tstf", {}).values())
        return sorted({node["style"] for curve in curves for node in curve.get("color", []) if "style" in node})


# The key path each attribute stands for; its docstring comes from the key table: that key's line,
# or for a section (a path ending in ".") the lines of the section's own key and every key in it.
_ATTRIBUTE_KEYS = {"compositor": "compositor", "ray": "ray.", "final_mode": "final", "camera": "camera.", "stf": "stf.",
                   "index_tstf": "tstf.index.", "gradient_tstf": "tstf.gradient.", "width": "image.width",
                   "height": "image.height", "background": "image.background"}


def _key_doc(key):
    text = f"{key['path']} ({key['type']}"
    text += f", default {key['default']})" if key["default"] else ")"
    return (text + ": " + key["allowed"]).replace("`", "")


def _document_attributes():
    keys = _native.scene_keys()
    for attribute, path in _ATTRIBUTE_KEYS.items():
        lines = [key for key in keys
                 if key["path"] == path or (path.endswith(".") and (key["path"].startswith(path) or key["path"] == path[:-1]))]
        getter = getattr(Scene, attribute)
        setattr(Scene, attribute, property(getter.fget, getter.fset, doc="\n".join(_key_doc(key) for key in lines)))


_document_attributes()


def _from_dict(content):
    content = dict(content)
    if not content.get("dataset"):
        content["dataset"] = _NO_DATASET
    return _native.scene_from_json(json.dumps(content), "scene")


def built_in_styles():
    """The names of the built-in lit-sphere styles (docs/styles.md)."""
    return list(_native.built_in_styles())
