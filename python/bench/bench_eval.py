"""Benchmark (not a test): Python ``Pps.eval`` of 10^6 points on koala.obj against the same
evaluation from Rust (``cargo bench --bench surface``, its ``eval_batch_f64`` line: the same
1 M points, the same Pps::eval_batch_f64) and against the same queries as ``ppm oracle``
JSON lines (a smaller batch, scaled). Results: docs/python.md, "Benchmark".

    python python/bench/bench_eval.py [--mesh ../shared/meshes/good/koala.obj] [--runs 3]
        [--oracle-points 20000] [--cargo-bench]   # --cargo-bench also runs the Rust side

Thread count: both sides use the rayon global pool (RAYON_NUM_THREADS, default: all cores);
the script prints it.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import pseudomanifold as pm

ROOT = Path(__file__).resolve().parents[2]


def bench_points(nf: int, n: int = 1_000_000) -> tuple[np.ndarray, np.ndarray]:
    """The points of benches/surface.rs ``points()``: the same 10^6 (face, bary)."""
    i = np.arange(n, dtype=np.int64)
    a = ((i * 7919) % 997).astype(np.float64) / 997.0
    b = ((i * 104729) % 991).astype(np.float64) / 991.0 * (1.0 - a)
    return i % nf, np.stack([1.0 - a - b, a, b], axis=1)


def timed(runs: int, f) -> float:
    t = []
    for _ in range(runs):
        t0 = time.perf_counter()
        f()
        t.append(time.perf_counter() - t0)
    return statistics.median(t)


def oracle_seconds(mesh: Path, lines: list[str]) -> float:
    cmd = [sys.executable, "-m", "pseudomanifold._cli", "oracle", "--mesh", str(mesh), "--bits", "53"]
    t0 = time.perf_counter()
    out = subprocess.run(cmd, input="\n".join(lines) + ("\n" if lines else ""), capture_output=True, text=True, check=True)
    dt = time.perf_counter() - t0
    bad = [l for l in out.stdout.splitlines() if '"ok":false' in l]
    if bad:
        raise SystemExit(f"oracle errors: {bad[:3]}")
    return dt


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mesh", default=str(ROOT.parent / "shared/meshes/good/koala.obj"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--oracle-points", type=int, default=20000)
    ap.add_argument("--cargo-bench", action="store_true", help="also run SURFACE_QUICK=1 cargo bench --bench surface")
    a = ap.parse_args()

    mesh = Path(a.mesh)
    print(f"threads (rayon): {pm.num_threads()}; mesh {mesh}")
    K = pm.load(mesh)
    t0 = time.perf_counter()
    M = K.pps()
    print(f"build: {time.perf_counter() - t0:.2f} s ({K.num_faces} faces)")
    f, b = bench_points(K.num_faces)
    n = len(f)
    M.eval(f[:1000], b[:1000], attributes="positions")  # warm-up
    t_pos = timed(a.runs, lambda: M.eval(f, b, attributes="positions"))
    t_curv = timed(a.runs, lambda: M.eval(f, b))
    py_rate = n / t_pos / 1e6
    print(f"python eval positions: {t_pos:.3f} s for {n} points = {py_rate:.3f} M points/s (median of {a.runs})")
    print(f"python eval positions+normals+curvatures: {t_curv:.3f} s = {n / t_curv / 1e6:.3f} M points/s")

    k = a.oracle_points
    lines = [json.dumps({"op": "eval", "face": int(f[i]), "bary": b[i].tolist()}) for i in range(k)]
    t_load = oracle_seconds(mesh, [])
    t_all = oracle_seconds(mesh, lines)
    per = max(t_all - t_load, 1e-9) / k
    print(
        f"ppm oracle JSON lines: {k} eval queries in {t_all:.2f} s, of which {t_load:.2f} s load+exit without queries;"
        f" {per * 1e6:.1f} µs per query -> {per * n:.1f} s scaled to {n} points"
    )
    print(f"ratio JSON lines / python: {per * n / t_pos:.1f}x")

    if a.cargo_bench:
        env = dict(os.environ, SURFACE_QUICK="1", SURFACE_RUNS=str(a.runs))
        out = subprocess.run(["cargo", "bench", "--bench", "surface"], cwd=ROOT, env=env, capture_output=True, text=True)
        m = re.search(r"eval_batch_f64 koala: ([0-9.]+) M points/s", out.stdout)
        if not m:
            print(out.stdout[-2000:], out.stderr[-2000:])
            raise SystemExit("no eval_batch_f64 koala line in the cargo bench output")
        rust_rate = float(m.group(1))
        print(f"rust eval_batch_f64 koala: {rust_rate:.3f} M points/s")
        print(f"ratio python time / rust time: {rust_rate / py_rate:.2f}x")


if __name__ == "__main__":
    main()
