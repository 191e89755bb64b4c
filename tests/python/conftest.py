"""Fixtures of the Python module's tests (run by ctest: tests/CMakeLists.txt sets the environment)."""

import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def backend():
    """The headless backend ctest runs this pass under (egl or osmesa); auto when run by hand."""
    return os.environ.get("TSTYLES_TEST_BACKEND", "auto")


@pytest.fixture(scope="session")
def tstyles_executable():
    executable = os.environ.get("TSTYLES_EXECUTABLE")
    if not executable:
        pytest.fail("TSTYLES_EXECUTABLE is not set (ctest sets it to build/tstyles)")
    return executable


@pytest.fixture(scope="session")
def realistic_datasets(tmp_path_factory):
    """The CF ocean NetCDF files (and others) of tests/data/realistic_datasets.h."""
    writer = os.environ.get("WRITE_REALISTIC_DATASETS")
    if not writer:
        pytest.fail("WRITE_REALISTIC_DATASETS is not set (ctest sets it)")
    folder = tmp_path_factory.mktemp("realistic")
    subprocess.run([writer, str(folder)], check=True)
    return folder


def run_cli(executable, *arguments):
    """`tstyles ARGUMENTS`: the exit code and stderr."""
    result = subprocess.run([executable, *map(str, arguments)], capture_output=True, text=True)
    return result.returncode, result.stderr
