"""tstyles.open reads in a reader process (docs/readers.md, "How reading is isolated"): libhdf5's crash
on a damaged file is a ValueError with the command line's message, and Python goes on; series are the
same as read in-process (TSTYLES_READ_IN_PROCESS=1)."""

from pathlib import Path

import numpy as np
import pytest

import tstyles
from conftest import run_cli
from test_series import assert_same_series

DAMAGED = Path(__file__).resolve().parents[1] / "data" / "damaged"


def test_a_library_crash_is_a_value_error_and_python_goes_on(tstyles_executable):
    damaged = DAMAGED / "netcdf4_hdf5_segv.nc"
    with pytest.raises(ValueError) as error:
        tstyles.open(damaged, var="temp")
    assert str(error.value).endswith(
        "the NetCDF/HDF5 library crashed while reading the variable list: the file is damaged")
    code, stderr = run_cli(tstyles_executable, "info", damaged, "--var", "temp")
    assert code == 2 and stderr.strip() == "tstyles: " + str(error.value)
    assert len(tstyles.Series(np.arange(16, dtype=np.float32).reshape(2, 2, 2, 2))) == 2  # still working


def test_series_read_isolated_equal_those_read_in_process(realistic_datasets, monkeypatch):
    for name in ["ocean-anomalies.nc", "moving-blob.nii"]:
        isolated = tstyles.open(realistic_datasets / name)
        monkeypatch.setenv("TSTYLES_READ_IN_PROCESS", "1")
        in_process = tstyles.open(realistic_datasets / name)
        monkeypatch.delenv("TSTYLES_READ_IN_PROCESS")
        assert isolated.source_format == in_process.source_format
        assert_same_series(isolated, in_process)
