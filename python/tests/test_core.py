"""The API of docs/python.md on bundled meshes (SPEC PY-*)."""

import json
import threading
import time

import numpy as np
import pytest

import pseudomanifold as pm
from conftest import CUBE, ICOSA, OCTA, ppm


def test_load_and_arrays(icosa):
    assert (icosa.num_vertices, icosa.num_faces) == (12, 20)
    k2 = pm.Surface(icosa.vertices, icosa.faces)
    assert k2.num_faces == 20
    rep = icosa.validation_report()
    assert rep["is_simplicial_surface"] is True
    assert all(c["verdict"] != "fails" for c in rep["checks"])


def test_validation_error_carries_ids_and_witnesses(icosa):
    F = icosa.faces[1:]  # remove one triangle: a boundary (Def. 3.1.6)
    with pytest.raises(pm.ValidationError) as e:
        pm.Surface(icosa.vertices, F)
    err = e.value
    assert err.checks and "boundary" in err.classes
    assert all(err.witnesses[i] for i in err.checks)
    assert err.report["is_simplicial_surface"] is False
    # An index out of range is reported by the validator, not by numpy or a panic.
    F = icosa.faces.copy()
    F[0, 0] = -1
    with pytest.raises(pm.ValidationError) as e:
        pm.Surface(icosa.vertices, F)
    assert "index_out_of_range" in e.value.classes
    with pytest.raises(pm.UsageError):
        pm.Surface(icosa.vertices[:, :2], icosa.faces)


def test_mesh_error_names_file_and_line(tmp_path):
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 x\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(pm.MeshError) as e:
        pm.load(bad)
    assert e.value.file == str(bad) and e.value.line == 2 and e.value.kind == "parse"
    with pytest.raises(pm.MeshError) as e:
        pm.load(tmp_path / "missing.off")
    assert e.value.kind == "io"
    assert isinstance(e.value, pm.PseudomanifoldError)


def test_eval_shapes_and_agreement(icosa_pps):
    rng = np.random.default_rng(1)
    n = 500
    f = rng.integers(0, 20, n)
    u = np.sort(rng.random((n, 2)), axis=1)
    b = np.stack([u[:, 0], u[:, 1] - u[:, 0], 1 - u[:, 1]], axis=1)
    out = icosa_pps.eval(f, b)
    assert out["positions"].shape == (n, 3) and out["normals"].shape == (n, 3)
    assert out["gaussian"].shape == (n,) and out["mean"].shape == (n,)
    assert all(np.isfinite(v).all() for v in out.values())
    assert np.allclose(np.linalg.norm(out["normals"], axis=1), 1.0)
    pos = icosa_pps.eval(f, b, attributes="positions")["positions"]
    assert np.abs(pos - out["positions"]).max() <= 1e-13
    # The sphere-like icosahedron surface: positive Gaussian curvature.
    assert (out["gaussian"] > 0).all()


def test_eval_errors_name_the_point(icosa_pps):
    with pytest.raises(pm.EvalError) as e:
        icosa_pps.eval([0, 99], [[1, 0, 0], [1, 0, 0]])
    assert e.value.index == 1 and e.value.face == 99
    with pytest.raises(pm.EvalError) as e:
        icosa_pps.eval([0], [[0.5, 0.6, 0.1]])
    assert e.value.index == 0
    with pytest.raises(pm.UsageError):
        icosa_pps.eval([0, 1], [[1, 0, 0]])


def test_sprime_and_sample(icosa, icosa_pps):
    V = icosa.vertices
    F = icosa.faces
    corners = icosa_pps.eval_sprime(np.repeat(np.arange(20), 3), np.tile(np.eye(3), (20, 1)))
    assert np.abs(corners - V[F.reshape(-1)]).max() <= 1e-15  # S' interpolates K's vertices
    V1, F1, attrs = icosa_pps.sample(1)
    assert F1.shape == (80, 3) and V1.shape == (42, 3)
    assert attrs["normals"].shape == (42, 3) and attrs["gaussian"].shape == (42,)


@pytest.mark.parametrize("sprime,profile", [("loop", "paper"), ("pn", "authors-code")])
def test_other_constructions(icosa, sprime, profile):
    m = icosa.pps(sprime=sprime, profile=profile)
    assert (m.sprime, m.profile) == (sprime, profile)
    out = m.eval([0, 5], [[0.2, 0.3, 0.5], [1 / 3, 1 / 3, 1 / 3]])
    assert np.isfinite(out["positions"]).all()
    with pytest.raises(pm.UsageError):
        icosa.pps(sprime="bezier")


def test_sigma_v(icosa):
    sv = icosa.sigma_v()
    p = sv.eval([0, 1], [[0.2, 0.3, 0.5], [1, 0, 0]])["positions"]
    assert p.shape == (2, 3) and np.isfinite(p).all()
    V, F, _ = sv.sample(1)
    assert F.shape == (80, 3)


def test_oracle_quantities(icosa, icosa_pps):
    o = icosa.oracle(bits=128)
    r = o.phi(0, [1, 5], [[0.3, 0.1], [0.3, 0.1]])
    # docs/oracle.md, worked example: phi_10 at (0.3, 0.1); (0.3, 0.1) is not in Omega_05.
    assert r["ok"].tolist() == [True, False]
    assert r["f64"][0].tolist() == [0.28918203890767846, 0.5651016080961618]
    assert r["value_str"][0][0].startswith("2.89182038907678357988")
    assert r["difference"][0] < 1e-15 and r["bits"] == 128
    assert r["errors"][0][:2] == (1, "not_in_domain")
    p = np.array([[0.1, 0.05], [0.3, -0.2], [0.0, 0.4]])
    for res in (o.g(0, p), o.g_inv(0, p), o.theta(0, p), o.gamma(0, p)):
        assert res["ok"].all() and (res["difference"] < 1e-12).all()
        assert np.abs(res["value"] - res["f64"]).max() < 1e-12
    m = o.member(0, 1, p)
    assert set(m["value"][:, 0]) <= {0.0, 1.0}
    # eval through the oracle is the same f64 eval as Pps.eval (positions).
    f, b = np.array([3, 7]), np.array([[0.25, 0.25, 0.5], [0.1, 0.2, 0.7]])
    e = o.eval(f, b)
    assert np.array_equal(e["f64"], icosa_pps.eval(f, b, attributes="positions")["positions"])
    assert o.handle_line('{"op":"degree","v":0}')["value"] == 5


def test_check_equals_cli_json(icosa):
    flags = ["--max-configs", "2", "--samples", "4", "--seed", "3"]
    cli = ppm("check", "--spec", "--json", *flags, ICOSA)
    assert cli.returncode == 0, cli.stderr
    want = json.loads(cli.stdout)
    got = pm.check(ICOSA, spec=True, max_configs=2, samples=4, seed=3)
    for r in (want, got):
        r.pop("seconds")
    assert got == want
    assert got.passes is True
    # From a Surface built from arrays: the same rows and verdicts (only the source differs).
    arr = pm.check(pm.Surface(icosa.vertices, icosa.faces), max_configs=2, samples=4, seed=3)
    assert [(c["id"], c["verdict"]) for c in arr.rows] == [(c["id"], c["verdict"]) for c in got.rows]
    with pytest.raises(pm.UsageError):
        pm.check(icosa, precision="mp:1")
    plain = pm.check(OCTA, spec=False)
    assert "chapter4" not in plain and plain.passes


def test_cli_console_script():
    assert ppm("check", CUBE).returncode == 0
    assert ppm("check", "/nonexistent.off").returncode == 2


def test_eval_releases_the_gil(icosa_pps):
    # While a long eval runs in one thread, another Python thread keeps running.
    n = 400_000
    f = np.arange(n) % 20
    b = np.tile([[0.2, 0.3, 0.5]], (n, 1))
    ticks = []
    t = threading.Thread(target=lambda: icosa_pps.eval(f, b))
    t.start()
    t0 = time.perf_counter()
    while t.is_alive():
        ticks.append(time.perf_counter() - t0)
        time.sleep(0.001)
    t.join()
    assert len(ticks) > 5, "the main thread was blocked during eval"
