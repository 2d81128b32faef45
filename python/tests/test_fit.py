"""Adaptive fitting from Python (SPEC AF-format-roundtrip): `ppm fit -o` writes a file that
`load_fit` reads back; its eval agrees with `ppm eval` on the same file to the last bit."""

import json

import numpy as np

import pseudomanifold as pm
from conftest import ppm

from pathlib import Path

# The bundled cube's fit passes every check (AF-*, SV-D3.4.1) at ε = 10⁻², so the round trip is
# tested on a fit with no failure to excuse.
CUBE = Path(__file__).resolve().parents[2] / "examples" / "meshes" / "cube.obj"


def test_load_fit_evaluates_as_ppm_eval(tmp_path):
    fit = tmp_path / "cube.fit"
    r = ppm("fit", CUBE, "--epsilon", "1e-2", "--relative", "--quiet", "--json", "-o", fit)
    report = json.loads(r.stdout)
    assert report["unexpected_failures"] == [], r.stdout
    assert all(c["examined"] > 0 for c in report["checks"] if c["verdict"] == "holds"), r.stdout
    assert fit.exists()
    s = pm.load_fit(fit)
    b = np.array([[0.2, 0.3, 0.5], [1 / 3, 1 / 3, 1 / 3]])
    p = s.eval(np.array([0, 1]), b)["positions"]
    assert np.isfinite(p).all()
    one = json.loads(ppm("eval", fit, 0, 0.2, 0.3, 0.5, check=True).stdout)
    assert one["point"] == p[0].tolist()
    v, f, _ = s.sample(1)
    assert f.shape[0] == 4 * report["base_faces"] and np.isfinite(v).all()


def test_load_fit_refuses_a_truncated_file(tmp_path):
    bad = tmp_path / "bad.fit"
    bad.write_text("ppm-fit 1\nepsilon 0.1\n")
    try:
        pm.load_fit(bad)
    except pm.MeshError as e:
        assert "bad.fit" in str(e)
    else:
        raise AssertionError("a truncated fit file was accepted")
