"""pseudomanifold.testing.assert_matches_reference: planted faults are caught with witnesses,
a correct implementation passes (SPEC PY-testing)."""

import numpy as np
import pytest

from conftest import ICOSA
from pseudomanifold.testing import assert_matches_reference, sample_points


def correct(pps, quantity="positions"):
    def fn(faces, bary):
        if quantity == "sprime":
            return pps.eval_sprime(faces, bary)
        return pps.eval(faces, bary)[quantity]

    return fn


def test_correct_implementation_passes(icosa_pps):
    for q, key in [("position", "positions"), ("normal", "normals"), ("gaussian", "gaussian"), ("mean", "mean"), ("sprime", "sprime")]:
        s = assert_matches_reference(correct(icosa_pps, key), icosa_pps, quantity=q, n=300, seed=5)
        assert s["points"] == 300 and s["worst_deviation"] <= s["atol"] + 1e-300 or q in ("gaussian", "mean")


def test_path_and_seed_are_reproducible(icosa_pps):
    a = sample_points(20, 50, 9)
    b = sample_points(20, 50, 9)
    assert all(np.array_equal(x, y) for x, y in zip(a, b))
    assert_matches_reference(correct(icosa_pps), ICOSA, n=100, seed=9)


def test_shift_at_one_face_is_caught(icosa_pps):
    ref = correct(icosa_pps)

    def shifted(faces, bary):
        p = ref(faces, bary)
        p[faces == 7] += 1e-3
        return p

    with pytest.raises(AssertionError) as e:
        assert_matches_reference(shifted, icosa_pps, n=400, seed=2)
    msg = str(e.value)
    assert "deviate" in msg and "face 7, bary (" in msg and "deviation 1.732e-03" in msg
    assert "theirs (" in msg and "reference (" in msg
    assert all("face 7," in line for line in msg.splitlines()[1:] if line.startswith("  face"))


def test_nan_is_caught(icosa_pps):
    ref = correct(icosa_pps)

    def with_nan(faces, bary):
        p = ref(faces, bary)
        p[3, 1] = np.nan
        return p

    with pytest.raises(AssertionError) as e:
        assert_matches_reference(with_nan, icosa_pps, n=50, seed=0)
    assert "1 of 50 points deviate" in str(e.value) and "nan" in str(e.value)


def test_wrong_shape_and_type_are_caught(icosa_pps):
    ref = correct(icosa_pps)
    with pytest.raises(AssertionError, match="wrong shape"):
        assert_matches_reference(lambda f, b: ref(f, b)[:, :2], icosa_pps, n=20)
    with pytest.raises(AssertionError, match="wrong shape"):
        assert_matches_reference(lambda f, b: ref(f, b)[:-1], icosa_pps, n=20)
    with pytest.raises(AssertionError, match="not a numeric array"):
        assert_matches_reference(lambda f, b: [["a", "b", "c"]] * len(f), icosa_pps, n=20)


def test_small_errors_within_tolerance_pass_and_wrong_curvature_fails(icosa_pps):
    ref = correct(icosa_pps)
    # 1e-12 of the diagonal: f64 rounding, within the tolerance derived from the precision.
    assert_matches_reference(lambda f, b: ref(f, b) + 1e-12, icosa_pps, n=100)
    g = correct(icosa_pps, "gaussian")
    with pytest.raises(AssertionError, match="gaussian"):
        assert_matches_reference(lambda f, b: g(f, b) * (1 + 1e-4), icosa_pps, quantity="gaussian", n=100)
