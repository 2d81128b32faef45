"""Dask runs (SPEC PY-certify-shards): a sharded certification on a local 2-worker cluster
equals `ppm certify`; check_directory merges per-mesh reports."""

import json
import shutil
import time

import pytest

distributed = pytest.importorskip("distributed")

import pseudomanifold as pm
from conftest import CUBE, ICOSA, OCTA, ppm
from pseudomanifold import _native
from pseudomanifold.distributed import certify, check_directory, strip_timings

# The size: every configuration up to degree 12 (2110 configurations; `ppm certify
# --max-degree 12 --jobs 2` measured 12.5 s wall, 24.8 s CPU in a release build).
M = 12


@pytest.fixture(scope="module")
def client():
    from dask.distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


def summary_rows(path):
    """The property rows of a summary without the time column (found by its header)."""
    lines = path.read_text().splitlines()
    header = next(l for l in lines if l.startswith("| property |")).split("|")
    t = [c.strip() for c in header].index("time (s, sum)")
    rows = [l.split("|") for l in lines if l.startswith("| `")]
    return [r[1:t] + r[t + 1 : -1] for r in rows]


def test_sharded_certify_equals_ppm_certify(client, tmp_path):
    t0 = time.perf_counter()
    res = certify(M, client, shards=6, out=tmp_path / "dask.json", summary=tmp_path / "dask.md")
    t_dask = time.perf_counter() - t0
    t0 = time.perf_counter()
    cli = ppm("certify", "--max-degree", M, "--jobs", "2", "--out", tmp_path / "cli.json", "--summary", tmp_path / "cli.md")
    t_cli = time.perf_counter() - t0
    assert cli.returncode == 0, cli.stderr
    ours = json.loads(_native.certify_read(str(tmp_path / "dask.json")))
    theirs = json.loads(_native.certify_read(str(tmp_path / "cli.json")))
    assert ours["configs"] == _native.certify_config_count(M) == 2110
    assert strip_timings(ours) == strip_timings(theirs)
    assert strip_timings(res["certificate"]) == strip_timings(theirs)
    # The summaries agree but for the wall time, the thread count and the time columns.
    assert summary_rows(tmp_path / "dask.md") == summary_rows(tmp_path / "cli.md") != []
    print(f"M = {M}: dask {t_dask:.1f} s (6 shards, 2 workers), ppm certify {t_cli:.1f} s")


def test_check_directory(client, tmp_path):
    for p in (ICOSA, OCTA, CUBE):
        shutil.copy(p, tmp_path / p.name)
    (tmp_path / "open.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    (tmp_path / "notes.txt").write_text("not a mesh")
    rep = check_directory(tmp_path, client, max_configs=1, samples=3)
    assert set(rep["meshes"]) == {ICOSA.name, OCTA.name, CUBE.name, "open.off"}
    assert rep["passes"][ICOSA.name] and rep["passes"][CUBE.name]
    assert rep["passes"]["open.off"] is False and rep["ok"] is False
    assert rep["meshes"]["open.off"]["is_simplicial_surface"] is False
    one = pm.check(ICOSA, max_configs=1, samples=3)
    got = dict(rep["meshes"][ICOSA.name])
    got.pop("seconds")
    one.pop("seconds")
    assert got["source"].endswith(ICOSA.name)
    got.pop("source"), one.pop("source")
    assert got == one
