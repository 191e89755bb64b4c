"""examples/python/ocean_max_change.py runs as a user would run it, on the CF ocean of tests/data."""

import os
import pathlib
import subprocess
import sys

import numpy as np

import tstyles

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python" / "ocean_max_change.py"


def test_the_ocean_example_writes_its_max_change_images(realistic_datasets, tmp_path):
    result = subprocess.run([sys.executable, str(EXAMPLE), str(realistic_datasets / "ocean-eddy.nc"), str(tmp_path)],
                            capture_output=True, text=True, env=dict(os.environ))
    assert result.returncode == 0, result.stderr
    assert "uploads: 1" in result.stdout
    image = tstyles.read_image(tmp_path / "ocean-max-change.png", dtype="uint8")
    assert image.shape == (400, 640, 4)
    # The eddy's change shows in the gradient TSTF's colours: blue to orange, not only the background.
    colours = np.unique(image.reshape(-1, 4), axis=0)
    assert len(colours) > 100
    # The turned views are pictures of their own: the same size, each one different.
    turned = [tstyles.read_image(tmp_path / f"ocean-max-change-azimuth{azimuth}.png", dtype="uint8")
              for azimuth in (-30, 0, 30)]
    assert all(view.shape == (200, 320, 4) for view in turned)
    assert all(len(np.unique(view.reshape(-1, 4), axis=0)) > 100 for view in turned)
    for i in range(3):
        for j in range(i + 1, 3):
            assert not np.array_equal(turned[i], turned[j]), f"views {i} and {j} are the same picture"
