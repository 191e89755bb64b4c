"""Builds the tstyles Python package with the project's CMake (scikit-build): the extension
module, the package's Python files, and, as the environment's data, the `tstyles` program, its
bundled styles, scenes and datasets (share/tstyles, found by the module relative to itself),
the man page and the desktop files. pyproject.toml says how to run it; docs/install.md."""

import pathlib
import re

from skbuild import setup

here = pathlib.Path(__file__).resolve().parent
project_cmake = (here.parent / "CMakeLists.txt").read_text()
version = re.search(r"^project\(\w+ VERSION ([0-9.]+)", project_cmake, re.MULTILINE).group(1)

setup(
    name="tstyles",
    version=version,
    description="Temporal Styles: time-varying volumes rendered with temporal compositors and "
                "temporal style transfer functions",
    license="MIT",
    python_requires=">=3.9",
    install_requires=["numpy"],
    extras_require={"xarray": ["xarray"]},
    packages=["tstyles"],
    # The whole project is the CMake source; the package is installed by python/CMakeLists.txt
    # into the install root's tstyles/, where scikit-build collects it.
    cmake_source_dir="..",
    cmake_args=["-DCMAKE_BUILD_TYPE=Release", "-DTSTYLES_TESTS=OFF", "-DTSTYLES_PYTHON_INSTALL_DIR=.",
                "-DTSTYLES_WARNINGS_AS_ERRORS=OFF"],
    zip_safe=False,
)
