"""tstyles.Renderer: the same pixels as `tstyles render`, one upload for many renders, no growth."""

import gc
import json

import numpy as np
import pytest

import tstyles
from conftest import run_cli


def moving_blob_steps():
    """Three time-steps of a blob moving along x, on grids of their own shapes, spacings and
    placements (one rotated), a missing corner in each and a mask on the second."""
    steps = []
    for index, (shape, spacing) in enumerate([((20, 22, 24), 0.05), ((18, 20, 26), 0.055), ((20, 20, 20), 0.06)]):
        z, y, x = np.meshgrid(*[np.linspace(-1.0, 1.0, n) for n in shape], indexing="ij")
        values = (np.exp(-((x - 0.4 * (index - 1)) ** 2 + y ** 2 + z ** 2) * 4.0) * 1000.0).astype(np.float32)
        values[:3, :3, :3] = np.nan
        steps.append({"values": values, "spacing": (spacing,) * 3, "origin": (0.1 * index, 0.0, 0.0),
                      "rotation": ((0.0, 0.0, 1.0), 20.0) if index == 2 else None,
                      "mask": (values > 300.0).astype(np.uint8) if index == 1 else None, "time": 2.0 * index})
    return steps


def series_of(steps):
    return tstyles.Series([s["values"] for s in steps], spacing=[s["spacing"] for s in steps],
                          origin=[s["origin"] for s in steps], rotation=[s["rotation"] for s in steps],
                          masks=[s["mask"] for s in steps], times=[s["time"] for s in steps])


def write_manifest(folder, steps):
    """The same data as a manifest folder (docs/dataset-format.md): float32 raw files, NaN missing."""
    folder.mkdir()
    entries = []
    for index, step in enumerate(steps):
        nz, ny, nx = step["values"].shape
        step["values"].astype("<f4").tofile(folder / f"t{index}.raw")
        entry = {"time": step["time"], "grid": {"type": "rectilinear", "dims": [nx, ny, nz], "spacing": list(step["spacing"])},
                 "placement": {"origin": list(step["origin"])}, "values": {"file": f"t{index}.raw", "type": "float32"}}
        if step["rotation"]:
            entry["placement"]["rotation"] = {"axis": list(step["rotation"][0]), "angle_deg": step["rotation"][1]}
        if step["mask"] is not None:
            step["mask"].tofile(folder / f"t{index}_mask.raw")
            entry["mask"] = {"file": f"t{index}_mask.raw"}
        entries.append(entry)
    manifest = {"format": "tstyles-series", "version": 1, "missing_value": "NaN", "time_steps": entries}
    (folder / "series.json").write_text(json.dumps(manifest))
    return folder


SCENE = {
    "image": {"width": 96, "height": 80, "background": [0.05, 0.05, 0.1, 1.0]},
    "camera": {"orbit": {"azimuth_deg": 35, "elevation_deg": 25}},
    "stf": {"opacity": [{"at": 0.05, "opacity": 0.0}, {"at": 0.6, "opacity": 0.7}],
            "color": [{"at": 0.0, "color": [0.9, 0.9, 0.9]}]},
    "compositor": "temporal-max-change",
    "tstf": {"gradient": {"range": "auto", "opacity": [{"at": 0, "opacity": 0.2}, {"at": 1, "opacity": 1}],
                          "color": [{"at": 0, "color": [0.2, 0.4, 1]}, {"at": 1, "color": [1, 0.5, 0]}]}},
}


def cli_render(executable, backend, tmp_path, name, *inputs):
    """`tstyles render INPUTS` to EXR (the renderer's floats) and PNG (8 bits, straight alpha)."""
    images = {}
    for extension in ("exr", "png"):
        output = tmp_path / f"{name}.{extension}"
        code, stderr = run_cli(executable, "render", *inputs, "-o", output, "--backend", backend)
        assert code == 0, stderr
        images[extension] = output
    return tstyles.read_image(images["exr"]), tstyles.read_image(images["png"], dtype="uint8")


def test_a_numpy_series_renders_the_pixels_of_its_manifest_through_the_cli(tmp_path, backend, tstyles_executable):
    steps = moving_blob_steps()
    dataset = write_manifest(tmp_path / "blob", steps)
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps({"dataset": "blob", **SCENE}))
    expected_float, expected_bytes = cli_render(tstyles_executable, backend, tmp_path, "scene", scene_file)
    auto_float, auto_bytes = cli_render(tstyles_executable, backend, tmp_path, "automatic", dataset)

    series = series_of(steps)
    with tstyles.Renderer(backend) as renderer:
        scene = tstyles.Scene.load(scene_file)
        image = renderer.render(series, scene, dtype="float32")
        assert image.shape == (80, 96, 4) and image.dtype == np.float32
        assert np.array_equal(image, expected_float)
        assert np.array_equal(renderer.render(series, scene), expected_bytes)
        automatic = renderer.render(series, dtype="float32")
        assert np.array_equal(automatic, auto_float)
        assert renderer.uploads == 1, "the automatic scene's display frame resolves to the scene file's"
    # The automatic scene is styled: a renderer's second styled frame of a series reads the gradient
    # atlas, where the CLI's one frame takes six fetches. A fresh renderer's first frame is the CLI's.
    with tstyles.Renderer(backend) as renderer:
        assert np.array_equal(renderer.render(series), auto_bytes)
    assert len(np.unique(expected_bytes.reshape(-1, 4), axis=0)) > 20, "the image shows something"


def test_an_image_shows_itself_as_the_png_the_cli_writes(tmp_path, backend):
    series = series_of(moving_blob_steps())
    with tstyles.Renderer(backend) as renderer:
        image = renderer.render(series, tstyles.Scene(SCENE))
    png = image._repr_png_()
    assert png.startswith(b"\x89PNG\r\n\x1a\n")
    (tmp_path / "shown.png").write_bytes(png)
    assert np.array_equal(tstyles.read_image(tmp_path / "shown.png", dtype="uint8"), image)
    image.save(tmp_path / "saved.png")
    assert np.array_equal(tstyles.read_image(tmp_path / "saved.png", dtype="uint8"), image)


def resident_bytes():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    raise AssertionError("no VmRSS in /proc/self/status")


def test_twenty_renders_with_one_renderer_upload_once_and_do_not_grow(backend):
    rng = np.random.default_rng(5)
    data = rng.random((4, 48, 48, 48)).astype(np.float32)  # 1.7 MiB of densities: a leaked copy would show
    series = tstyles.Series(data)
    renderer = tstyles.Renderer(backend)
    scenes = []
    for index in range(20):
        scene = tstyles.Scene.automatic(series)
        scene.update({"compositor": ["temporal-mip", "temporal-average", "temporal-max-change"][index % 3],
                      "camera": {"orbit": {"azimuth_deg": 18 * index, "elevation_deg": 20}}})
        scene.set("tstf.gradient.range", [0.0, 0.2 + 0.02 * index])
        scenes.append(scene)
    uploads_before = tstyles.upload_count()
    # Every program compiled once before measuring: each compositor's, and the automatic scene's
    # styles take their gradients with six fetches in a series' first styled frame and from the
    # gradient atlas from the second on (made then, once), so the first compositor's twice.
    for scene in scenes[:4]:
        renderer.render(series, scene, 128, 128)
    gc.collect()
    before = resident_bytes()
    for scene in scenes:
        image = renderer.render(series, scene, 128, 128)
        del image
    gc.collect()
    grown = resident_bytes() - before
    assert renderer.uploads == 1 and tstyles.upload_count() == uploads_before + 1
    # Each render makes a 256 KiB float image and a 64 KiB byte image; 20 of them kept would be
    # 6.4 MiB, a kept copy of the series 7 MiB each. 2 MiB leaves room for the allocator's slack.
    assert grown < 2 * 1024 * 1024, f"resident memory grew by {grown} bytes over 20 renders"
    scenes[0]["orientation"] = ["+x", "+z", "-y"]  # another display frame: the series is turned and uploaded again
    renderer.render(series, scenes[0], 64, 64)
    assert renderer.uploads == 2
    renderer.close()


def test_render_errors_are_value_errors_with_the_cli_message(backend):
    series = tstyles.Series(np.random.default_rng(6).random((2, 4, 4, 4)))
    with tstyles.Renderer(backend) as renderer:
        with pytest.raises(ValueError) as error:
            renderer.render(series, tstyles.Scene({"exposure": {"first": 5}}), 32, 32)
        assert "exposure.first" in str(error.value)
        with pytest.raises(ValueError) as error:
            tstyles.Scene({"compositor": "temporal-median"})
        assert str(error.value).startswith("scene: compositor: ")


def allowed_in_key_table(path):
    return next(key for key in tstyles.Scene.keys() if key["path"] == path)["allowed"].replace("`", "")


def test_the_compositor_names_are_the_scene_readers():
    # _native lists no compositors: the reader's own list is the one in its message for an unknown name.
    with pytest.raises(ValueError) as error:
        tstyles.Scene({"compositor": "temporal-median"})
    allowed = str(error.value).split("; allowed values: ", 1)[1].split(", ")
    assert len(allowed) == 12
    # The attribute's docstring is the key table's line for "compositor", which names them all.
    assert allowed_in_key_table("compositor") in tstyles.Scene.compositor.__doc__
    for name in allowed:
        assert name in tstyles.Scene.compositor.__doc__
        compositor = tstyles.Scene({"compositor": name}).compositor  # with its options' defaults: an object
        assert (compositor if isinstance(compositor, str) else compositor["name"]) == name


def test_the_default_scene_reads_and_writes():
    # Scene() is the scene reader's defaults, as Scene({}) is: it reads, writes and compares.
    scene = tstyles.Scene()
    assert scene.compositor == tstyles.Scene({}).compositor
    assert json.loads(scene.to_json()) == tstyles.Scene({}).to_dict()
    assert scene == tstyles.Scene({})


def test_the_attributes_are_documented_from_the_key_table():
    keys = {key["path"]: key for key in tstyles.Scene.keys()}
    assert keys["image.width"]["allowed"] == "in [1, 16384]" and keys["image.width"]["whole"]
    assert tstyles.Scene.width.__doc__ == "image.width (integer, default 512): in [1, 16384]"
    assert "rays stop at this accumulated opacity" in keys["raycast.termination"]["allowed"]


def test_the_ray_mode_is_an_attribute_that_renders(backend):
    # Issue 50: scene.ray reads "composite" where the file leaves it out, takes a name or an object
    # with the mode's options, refuses what the reader refuses, and renders another picture.
    series = series_of(moving_blob_steps())
    scene = tstyles.Scene(dict(SCENE, compositor="temporal-mip"))
    assert scene.ray == "composite"
    assert "ray.values" in tstyles.Scene.ray.__doc__ and "isosurface" in tstyles.Scene.ray.__doc__
    with tstyles.Renderer(backend) as renderer:
        composite = renderer.render(series, scene, dtype="float32")
        scene.ray = "maximum"
        assert scene.ray == "maximum"
        maximum = renderer.render(series, scene, dtype="float32")
        scene.ray = {"mode": "isosurface", "values": [0.3, 0.6]}
        assert scene.ray == {"mode": "isosurface", "values": [0.3, 0.6], "opacities": [1.0, 1.0]}
        isosurface = renderer.render(series, scene, dtype="float32")
    assert not np.array_equal(composite, maximum) and not np.array_equal(maximum, isosurface)
    with pytest.raises(ValueError) as error:
        scene.ray = {"mode": "maximum", "values": [0.5]}
    assert "maximum takes no values" in str(error.value)
    with pytest.raises(ValueError) as error:
        tstyles.Scene(dict(SCENE, compositor="temporal-average", ray="maximum"))
    assert "ray.mode: maximum compares a value along the ray" in str(error.value)
