# Where did the ocean warm or cool the most? One image of a CF NetCDF ocean's temporal maximum
# density change, from xarray, in a script or cell by cell in Jupyter (the "# %%" markers are cells
# in VS Code, Spyder and jupytext). docs/python.md explains each call.
#
#   PYTHONPATH=build/python python3 examples/python/ocean_max_change.py OCEAN.nc [OUTPUT_FOLDER]
#
# OCEAN.nc: any NetCDF with a 4D (time, depth, lat, lon) variable; `build/tests/write_realistic_datasets
# DIR` writes one (DIR/ocean-eddy.nc, six months of a warm eddy drifting east).

# %% Open the dataset with xarray and pick the variable
import pathlib
import sys

import xarray as xr

import tstyles

ocean_file = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path("ocean-eddy.nc")
output = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else pathlib.Path(".")
dataset = xr.open_dataset(ocean_file)
temperature = dataset["thetao"]  # (time, depth, lat, lon), degrees Celsius, land as NaN
print(temperature.dims, temperature.sizes["time"], "time-steps")

# %% The series: coordinates, CF attributes and dates as the NetCDF reader reads them
series = tstyles.from_xarray(temperature)
print(series)
print("times:", ", ".join(series.time_labels))

# %% The automatic scene (map view, north up, surface on top), then the temporal max density change
scene = tstyles.Scene.automatic(series)
print("\n".join(scene.explanation))
scene.compositor = "temporal-max-change"
scene.set("tstf.gradient.color", [{"at": 0.0, "color": [0.15, 0.3, 0.9]}, {"at": 1.0, "color": [1.0, 0.35, 0.1]}])

# %% Render it: a numpy array (height, width, 4) that shows itself in Jupyter
renderer = tstyles.Renderer()
image = renderer.render(series, scene, width=640, height=400)
print(image.shape, image.dtype, "rendered by", renderer.description)

# %% Turn the camera: the series stays on the GPU (one upload for every view)
views = []
for azimuth in (-30, 0, 30):
    scene.set("camera.orbit.azimuth_deg", azimuth)
    views.append(renderer.render(series, scene, width=320, height=200))
print("uploads:", renderer.uploads)

# %% Save, or show: in Jupyter the last expression of a cell displays the image
image.save(output / "ocean-max-change.png")
for azimuth, view in zip((-30, 0, 30), views):
    view.save(output / f"ocean-max-change-azimuth{azimuth}.png")
print("wrote", output / "ocean-max-change.png")
image
