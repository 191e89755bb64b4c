"""DICOM series through tstyles.open: the values, geometry, times and series choice that pydicom wrote
(tests/data/dicom_samples.py) come back exactly. No OpenGL needed."""

import math
import os
import sys

import numpy as np
import pytest

import tstyles

sys.path.insert(0, os.path.join(os.path.dirname(__file__), os.pardir, "data"))
import dicom_samples as samples  # noqa: E402


def normalised(values, low, high):
    """The density the C++ model stores: (v - low) / (high - low) in double, then float32."""
    return np.clip((np.asarray(values, dtype=np.float64) - low) / (high - low), 0.0, 1.0).astype(np.float32)


def rotation_matrix(axis, angle_deg):
    axis = np.asarray(axis, dtype=np.float64)
    axis /= np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    angle = math.radians(angle_deg)
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * (k @ k)


LPS_TO_RAS = np.diag([-1.0, -1.0, 1.0])


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    folder = tmp_path_factory.mktemp("dicom")
    for name in ("cine", "ct", "enhanced"):
        samples.SAMPLES[name](str(folder))
    return folder


def test_the_4d_cine_comes_back_as_written(written):
    series = tstyles.open(written / "cine")
    assert series.source_format == "DICOM" and series.name == "cine short axis"
    assert len(series) == samples.CINE_STEPS
    assert list(series.times) == [t * samples.CINE_TRIGGER_MS for t in range(samples.CINE_STEPS)]
    assert series.time_units == "milliseconds"
    assert [(a["unit"], a["direction"]) for a in series.axes] == [("mm", "right"), ("mm", "anterior"),
                                                                    ("mm", "superior")]
    nx, ny, nz = samples.CINE_DIMS
    low, high = series.value_range
    assert (low, high) == (0.0, float(samples.cine_value(3, 5, 11, 15)))
    for t in range(samples.CINE_STEPS):
        expected = np.array([[[samples.cine_value(t, z, y, x) for x in range(nx)] for y in range(ny)]
                             for z in range(nz)])
        assert np.array_equal(series.density(t), normalised(expected, low, high))
        step = series.step(t)
        assert step["dims"] == (nx, ny, nz)
        assert step["spacing"] == pytest.approx(samples.CINE_SPACING, abs=1e-9)


def test_the_oblique_cine_is_placed_in_ras(written):
    step = tstyles.open(written / "cine").step(0)
    row, column = samples.cine_cosines()
    normal = np.cross(row, column)
    # Grid x, y, z run along the row, column and normal directions, turned from LPS to RAS.
    expected = LPS_TO_RAS @ np.column_stack([row, column, normal])
    assert rotation_matrix(*step["rotation"]) == pytest.approx(expected, abs=1e-6)
    assert step["origin"] == pytest.approx(tuple(LPS_TO_RAS @ np.array(samples.CINE_ORIGIN)), abs=1e-9)


def test_the_series_is_chosen_by_number_or_uid(written):
    scout = tstyles.open(written / "cine", series=1)
    assert len(scout) == 1 and scout.step(0)["dims"] == (8, 8, 3)
    assert scout.step(0)["spacing"] == (2.0, 2.0, 5.0)
    cine = tstyles.open(written / "cine", series=samples.CINE_UID)
    assert len(cine) == samples.CINE_STEPS
    with pytest.raises(ValueError, match="names no series here"):
        tstyles.open(written / "cine", series="1.2.3")


def test_ct_values_are_hounsfield_units_on_uneven_slices(written):
    series = tstyles.open(written / "ct")
    assert series.value_unit == "HU" and len(series) == 1
    nx, ny, nz = samples.CT_DIMS
    expected = np.array([[[samples.ct_stored(z, y, x) - 1024 for x in range(nx)] for y in range(ny)]
                         for z in range(nz)])
    low, high = series.value_range
    assert (low, high) == (expected.min(), expected.max())
    assert np.array_equal(series.density(0), normalised(expected, low, high))
    step = series.step(0)
    assert step["positions"] == {"z": list(samples.CT_SLICE_Z)}
    assert step["origin"] == (5.0, 4.0, 0.0)
    # Axial slices: rows toward the patient's left, columns toward the back, turned to RAS.
    assert rotation_matrix(*step["rotation"]) == pytest.approx(LPS_TO_RAS, abs=1e-12)


def test_the_enhanced_multiframe_file_comes_back_as_written(written):
    series = tstyles.open(written / "enhanced.dcm")
    assert len(series) == samples.ENH_STEPS
    assert list(series.times) == [t * samples.ENH_SECONDS for t in range(samples.ENH_STEPS)]
    assert series.time_units == "seconds"
    nx, ny, nz = samples.ENH_DIMS
    low, high = series.value_range
    for t in range(samples.ENH_STEPS):
        expected = np.array([[[samples.enhanced_stored(t, z, y, x) * samples.ENH_SLOPE + samples.ENH_INTERCEPT
                               for x in range(nx)] for y in range(ny)] for z in range(nz)])
        assert np.array_equal(series.density(t), normalised(expected, low, high))
    step = series.step(0)
    assert step["spacing"] == (1.0, 1.5, 2.0)
    # Rows toward posterior, columns toward the feet, slices toward the patient's right (LPS -x).
    expected = LPS_TO_RAS @ np.column_stack([(0, 1, 0), (0, 0, -1), (-1, 0, 0)])
    assert rotation_matrix(*step["rotation"]) == pytest.approx(expected, abs=1e-9)
    assert step["origin"] == pytest.approx((0.0, -10.0, 40.0), abs=1e-12)


def test_phases_of_one_study_are_time_steps(tmp_path):
    """The multi-phase CT: found by default (series 3, 5, 4 in acquisition order), or chosen with
    series="3,4"; the HU of each phase as written."""
    samples.SAMPLES["phases"](str(tmp_path))
    series = tstyles.open(tmp_path / "phases")
    assert series.name == "arterial, portal venous, delayed"
    assert list(series.times) == [0.0, 50.0, 160.0] and series.time_units == "seconds"
    assert series.value_unit == "HU"
    nx, ny, nz = samples.PHASE_DIMS
    low, high = series.value_range
    for phase in range(3):
        expected = np.array([[[samples.phase_value(phase, z, y, x) for x in range(nx)] for y in range(ny)]
                             for z in range(nz)])
        assert np.array_equal(series.density(phase), normalised(expected, low, high))
    chosen = tstyles.open(tmp_path / "phases", series="3,4")
    assert chosen.name == "arterial, delayed" and list(chosen.times) == [0.0, 160.0]
    with pytest.raises(ValueError, match="series 2 is 12 x 10 x 5 voxels, not 8 x 8 x 3 of series 1"):
        tstyles.open(tmp_path / "phases", series="all")


def test_rt_dose_is_placed_by_its_frame_offsets_in_gray(tmp_path):
    samples.SAMPLES["rtdose"](str(tmp_path))
    series = tstyles.open(tmp_path / "rtdose" / "dose.dcm")
    assert series.value_unit == "Gy" and len(series) == 1
    step = series.step(0)
    assert step["dims"] == samples.DOSE_DIMS and step["spacing"] == (2.0, 2.5, 3.0)
    nx, ny, nz = samples.DOSE_DIMS
    expected = np.array([[[samples.dose_stored(z, y, x) * samples.DOSE_SCALING for x in range(nx)] for y in range(ny)]
                         for z in range(nz)])
    low, high = series.value_range
    # Values are decoded to float32 (stored x DoseGridScaling), so the range is the float32 of each end.
    assert (low, high) == (float(np.float32(expected.min())), float(np.float32(expected.max())))
    assert np.allclose(series.density(0), normalised(expected, low, high), rtol=0, atol=1e-6)
